#include "render_controller.h"

#include <algorithm>
#include <cmath>

#include "image/image_io.h"
#include "render/dispersion_split.h"
#include "render/integrator_names.h"
#include "render/progressive_render.h"
#include "scene/render_tone_map.h"

namespace lenslab::gui {

QImage to_qimage(const Film& film, const ToneMap& tone) {
    const Image8 img = to_srgb8(film, tone);
    QImage out(img.width, img.height, QImage::Format_RGB888);
    for (int y = 0; y < img.height; ++y) {
        std::copy_n(img.rgb.data() + size_t(y) * img.width * 3, img.width * 3, out.scanLine(y));
    }
    return out;
}

RenderController::RenderController(QObject* parent, int preview_size)
    : QThread(parent), m_preview_size(preview_size) {
    m_debounce.setSingleShot(true);
    connect(&m_debounce, &QTimer::timeout, this, &RenderController::start_pending);
    start();
}

RenderController::~RenderController() {
    {
        const std::lock_guard lock(m_mutex);
        m_quit = true;
        if (m_control) m_control->cancel();
        m_wake.notify_all();
    }
    wait();
}

void RenderController::restart(const Scene& scene, int delay_ms, RenderQuality quality) {
    Scene preview = scene;
    // The view's integrator renders media too (sppm's volume photons: an atmosphere, a shape's).
    if (!m_use_scene_integrator) preview.render.integrator = integrators::kView;
    const int largest = std::max(preview.render.width, preview.render.height);
    const int limit = quality == RenderQuality::Draft ? std::max(1, m_preview_size / kDraftDivisor)
                                                      : m_preview_size;
    if (largest > limit) {
        const double s = double(limit) / largest;
        preview.render.width = std::max(1, int(std::lround(preview.render.width * s)));
        preview.render.height = std::max(1, int(std::lround(preview.render.height * s)));
    }
    m_next = std::move(preview);
    {
        // Cancel the pass in flight now, so the worker is free when the debounce ends.
        const std::lock_guard lock(m_mutex);
        if (m_control) m_control->cancel();
    }
    m_debounce.start(delay_ms);
}

void RenderController::start_pending() {
    if (!m_next) return;
    const std::lock_guard lock(m_mutex);
    m_job = std::move(m_next);
    m_next.reset();
    m_stop = false;
    if (m_control) m_control->cancel();
    m_wake.notify_all();
}

void RenderController::stop_rendering() {
    m_debounce.stop();
    m_next.reset();
    const std::lock_guard lock(m_mutex);
    m_stop = true;
    m_job.reset();
    if (m_control) m_control->cancel();
    m_wake.notify_all();  // a paused worker
}

void RenderController::set_paused(bool paused) {
    const std::lock_guard lock(m_mutex);
    m_paused = paused;
    m_wake.notify_all();
}

bool RenderController::is_rendering() const {
    const std::lock_guard lock(m_mutex);
    return m_busy;
}

Film RenderController::last_film() const {
    const std::lock_guard lock(m_mutex);
    return m_last;
}

void RenderController::render_preview(Scene& scene, bool spectrum_held) {
    RenderSettings& s = scene.render;
    const int limit = std::max(1, m_preview_size / kDraftDivisor);
    // photon_map traces its photons whatever the size, as does sppm given its photon count.
    const bool scales = s.integrator != integrators::kPhotonMap &&
                        !(s.integrator == integrators::kSppm && s.pass_photons > 0);
    if (!spectrum_held && (!scales || std::max(s.width, s.height) <= limit)) return;
    const int width = s.width, height = s.height;
    const std::string integrator = s.integrator;
    if (spectrum_held) s.integrator = integrators::kWhitted;
    const double scale = std::min(1.0, double(limit) / std::max(width, height));
    s.width = std::max(1, int(std::lround(width * scale)));
    s.height = std::max(1, int(std::lround(height * scale)));
    RenderControl control;
    if (begin_pass(control)) {
        const ForgetControl forget{this};
        ProgressiveRender preview(scene);
        if (preview.add_pass(control))
            emit preview_ready(to_qimage(preview.image(), tone_map_for(s)));
    }
    s.width = width;
    s.height = height;
    s.integrator = integrator;
}

bool RenderController::resume() {
    const std::lock_guard lock(m_mutex);
    if (!m_stopped_resumable || m_job) return false;
    m_resume = true;
    m_wake.notify_all();
    return true;
}

bool RenderController::wait_for_resume() {
    std::unique_lock lock(m_mutex);
    if (!m_stop || m_job || m_quit) return false;
    m_stopped_resumable = true;
    m_busy = false;
    m_wake.wait(lock, [this] { return m_resume || m_quit || m_job; });
    m_stopped_resumable = false;
    const bool resumed = m_resume && !m_quit && !m_job;
    m_resume = false;
    m_busy = true;
    if (resumed) m_stop = false;
    return resumed;
}

bool RenderController::begin_pass(RenderControl& control) {
    std::unique_lock lock(m_mutex);
    m_wake.wait(lock, [this] { return !m_paused || m_quit || m_stop || m_job; });
    if (m_quit || m_stop || m_job) return false;  // a newer scene waits, or stopped
    m_control = &control;
    return true;
}

RenderController::ForgetControl::~ForgetControl() {
    const std::lock_guard lock(owner->m_mutex);
    owner->m_control = nullptr;
}

void RenderController::run() {
    for (;;) {
        Scene scene;
        {
            std::unique_lock lock(m_mutex);
            m_wake.wait(lock, [this] { return m_quit || m_job; });
            if (m_quit) return;
            scene = std::move(*m_job);
            m_job.reset();
            m_busy = true;
        }
        emit rendering_changed(true);
        QElapsedTimer clock;
        clock.start();
        RenderEnd end = RenderEnd::Restarted;
        int passes = 0;
        // Stop was asked for (not a newer scene, not the editor closing).
        const auto stop_asked = [this] {
            const std::lock_guard lock(m_mutex);
            return m_stop && !m_job && !m_quit;
        };
        // Stopped: report it, keep the render and wait; true when resume() asks for more
        // passes.
        const auto stopped_and_resumed = [&](int done) {
            if (!stop_asked()) return false;
            emit rendering_changed(false);
            emit render_ended(RenderEnd::Stopped, done);
            if (!wait_for_resume()) return false;
            emit rendering_changed(true);
            return true;
        };
        // Held only where whitted can preview it: it renders no media.
        const bool spectrum_held = scene.render.integrator == integrators::kSppm &&
                                   dispersion_samples(scene) > 1 && !scene.has_media();
        const int first_shown = spectrum_held ? kSpectrumPasses : 1;
        try {
            render_preview(scene, spectrum_held);
            ProgressiveRender render(scene);
            const auto show = [&](const Film& film) {
                const double seconds = clock.elapsed() / 1000.0;
                emit frame_ready(to_qimage(film, tone_map_for(scene.render)), render.passes(),
                                 qint64(render.stats(seconds).photons), seconds,
                                 QString::fromStdString(scene.render.integrator));
            };
            while (render.passes() < m_max_passes) {
                RenderControl control;
                bool finished = false;
                if (begin_pass(control)) {
                    // Forgotten before `control` goes, also when the pass throws (a refused
                    // render): restart() would otherwise cancel a dead stack object (ASan
                    // caught it).
                    const ForgetControl forget{this};
                    finished = render.add_pass(control);
                }
                // Not begun, or cut short (its sums left as they were): after Stop, resumable,
                // showing what a held-back render has.
                if (!finished) {
                    if (render.passes() > 0 && render.passes() < first_shown && stop_asked()) {
                        show(render.image());
                    }
                    if (!stopped_and_resumed(passes)) break;
                    continue;
                }
                const Film film = render.image();
                {
                    const std::lock_guard lock(m_mutex);
                    m_last = film;
                }
                passes = render.passes();
                if (passes >= first_shown || passes >= m_max_passes) show(film);
            }
            if (passes >= m_max_passes) end = RenderEnd::Converged;
        } catch (const std::exception& e) {
            end = RenderEnd::Failed;
            emit render_failed(QString::fromStdString(e.what()));
        }
        bool quitting = false;
        {
            const std::lock_guard lock(m_mutex);
            m_busy = false;
            quitting = m_quit;
            if (end == RenderEnd::Restarted && m_stop && !m_job) end = RenderEnd::Stopped;
        }
        emit rendering_changed(false);
        if (!quitting) emit render_ended(end, passes);
    }
}

}  // namespace lenslab::gui
