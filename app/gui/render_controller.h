#pragma once
// Renders the scene progressively on a worker thread: pass after pass, each frame sent back
// through a queued signal. The view uses sppm, whose passes converge to the full solution
// (caustics, interreflection), unless told to use the scene's own integrator. A new scene (after an
// edit) cancels the pass in flight and starts again; restarts are debounced so a burst of edits
// costs one restart. The worker renders an immutable copy of the scene; it never touches the
// document.

#include <QElapsedTimer>
#include <QImage>
#include <QThread>
#include <QTimer>
#include <condition_variable>
#include <mutex>
#include <optional>

#include "image/film.h"
#include "image/tone_map.h"
#include "render/render_control.h"
#include "scene/scene.h"

namespace lenslab::gui {

// Why a render stopped adding passes.
enum class RenderEnd {
    Converged,  // it reached the pass limit
    Stopped,    // Stop was asked for
    Restarted,  // a newer scene took its place
    Failed,     // the integrator refused (render_failed says why)
};

// Full: the preview size; Draft: a quarter of it in each direction, for frames that must come
// at once while something is dragged (16 times fewer pixels).
enum class RenderQuality { Full, Draft };

class RenderController : public QThread {
    Q_OBJECT

public:
    // `preview_size`: the larger image side is scaled down to at most this many pixels.
    explicit RenderController(QObject* parent = nullptr, int preview_size = 640);
    ~RenderController() override;

    // Schedules a render of `scene` (debounced by `delay_ms`; 0 starts at once).
    void restart(const Scene& scene, int delay_ms = 120,
                 RenderQuality quality = RenderQuality::Full);
    // Stops after cancelling the pass in flight; the last frame stays, and so does what the
    // passes summed, for resume().
    void stop_rendering();
    // Goes on from where Stop left the render (its passes kept) and returns true; false when
    // there is nothing to resume (no render was stopped, or a newer scene replaced it).
    bool resume();
    bool is_rendering() const;
    // Paused, the worker finishes the pass in flight and waits, keeping what it has summed;
    // resumed, it goes on from there (an export renders meanwhile on all the cores). Stop and
    // a new scene still end the paused render.
    void set_paused(bool paused);
    int max_passes() const { return m_max_passes; }
    void set_max_passes(int n) { m_max_passes = n; }
    // false (the default): render with sppm; true: with the scene's `render.integrator`.
    // Takes effect at the next restart.
    bool uses_scene_integrator() const { return m_use_scene_integrator; }
    void set_use_scene_integrator(bool on) { m_use_scene_integrator = on; }
    // The latest averaged frame in linear RGB, for export.
    Film last_film() const;

signals:
    // `passes`: passes done; `photons`: photons emitted so far (sppm) or stored in the photon
    // maps (photon_map), else 0; `integrator`: the one rendering.
    void frame_ready(const QImage& image, int passes, qint64 photons, double seconds,
                     const QString& integrator);
    void render_failed(const QString& message);
    // The first moments of a full-size restart: one pass at the draft size, to show until
    // the first full-size frame comes (for integrators whose pass cost follows the pixels).
    void preview_ready(const QImage& image);
    // The render ended after `passes` passes (not sent when the editor closes).
    void render_ended(lenslab::gui::RenderEnd end, int passes);
    void rendering_changed(bool rendering);

protected:
    void run() override;

private:
    void start_pending();
    // Makes `control` the pass in flight (waiting while paused), unless the render is to end:
    // the editor closes, Stop, or a newer scene waits.
    bool begin_pass(RenderControl& control);
    // After Stop: waits, the render kept, until resume() (true) or a newer scene or the
    // editor closing (false).
    bool wait_for_resume();
    // Renders and emits the restart's draft preview of `scene` (the worker's own copy, its
    // size and integrator restored after); skipped where a pass costs as much at any size.
    // `spectrum_held`: sppm's first frames are held back (kSpectrumPasses), so the preview
    // is whitted's, at any size.
    void render_preview(Scene& scene, bool spectrum_held);
    // Clears m_control when the pass it points to ends, however it ends.
    struct ForgetControl {
        RenderController* owner;
        ~ForgetControl();
    };

    QTimer m_debounce;
    std::optional<Scene> m_next;  // GUI thread only: the scene waiting for the debounce
    int m_preview_size;
    static constexpr int kDraftDivisor = 4;
    // sppm follows one wavelength a pass where glass disperses (render/pass_wavelength.h, van
    // der Corput over the passes), so one pass shows a dispersive lens purple or cyan: such a
    // render's frames are shown from this many passes on, spread over the spectrum, after a
    // colour-clean preview (whitted, its paths split over the spectrum).
    static constexpr int kSpectrumPasses = 8;
    int m_max_passes = 256;
    bool m_use_scene_integrator = false;

    // std:: rather than QMutex/QWaitCondition: ThreadSanitizer sees pthread's locks, not the
    // futexes inside Qt's (uninstrumented) library.
    mutable std::mutex m_mutex;
    std::condition_variable m_wake;
    std::optional<Scene> m_job;          // handed to the worker
    RenderControl* m_control = nullptr;  // the pass in flight, to cancel it
    bool m_quit = false, m_stop = false, m_busy = false, m_paused = false;
    bool m_stopped_resumable = false;  // the worker keeps a stopped render, waiting
    bool m_resume = false;             // asked to go on with it
    Film m_last;
};

// 8-bit sRGB image of a linear film through the scene's tone map, for display.
QImage to_qimage(const Film& film, const ToneMap& tone = {});

}  // namespace lenslab::gui
