#pragma once
// The editor's main window: scene tree (left), the 3-D viewport and the 2-D section view
// as tabs (centre), properties (right), menus for files, edits and rendering, and a status
// bar: the render's state (its pass of the limit, converged, stopped or why it failed),
// photons and time, and a progress bar.

#include <QDeadlineTimer>
#include <QLabel>
#include <QMainWindow>
#include <QProgressBar>
#include <QTabWidget>

namespace lenslab {
struct ElementEdit;
}  // namespace lenslab

namespace lenslab::gui {

class DetectorDock;
class PropertyPanel;
class OptimiseDialog;
class ToleranceDialog;
class RayDiagramDock;
class RenderController;
class SceneDocument;
class SceneTree;
class SectionTab;
class SectionWidget;
class Viewport;
enum class RenderEnd;  // render_controller.h

class MainWindow : public QMainWindow {
    Q_OBJECT

public:
    explicit MainWindow(QWidget* parent = nullptr);
    ~MainWindow() override;

    // Opens a scene file. A broken file leaves the current scene as it is; its error is
    // returned in `error` if given, else shown in a message box.
    // The dialog File ▸ Open shows for a file it cannot open (also for a file given on the
    // command line).
    void show_open_error(const QString& message);
    // `as_copy`: untitled (the examples), so Save asks where (SceneDocument::open).
    bool open_file(const QString& path, QString* error = nullptr, bool as_copy = false);
    bool save_file(const QString& path, QString* error = nullptr);
    // Renders the scene at its own resolution with its own integrator, behind a progress
    // dialog that can cancel it, and writes it to `path` (.png or .exr), atomically: a failure
    // leaves no file and no temporary behind. The error is returned in `error` if given,
    // else shown.
    bool export_image_to(const QString& path, QString* error = nullptr);

    SceneDocument* document() const { return m_document; }
    RenderController* renderer() const { return m_renderer; }
    SceneTree* tree() const { return m_tree; }
    PropertyPanel* panel() const { return m_panel; }
    Viewport* viewport() const { return m_viewport; }
    SectionWidget* section_view() const { return m_section; }
    // Brings the "3d" or "section" view to the front; false for another name.
    bool show_view(const QString& name);
    RayDiagramDock* ray_diagram() const { return m_ray_diagram; }
    DetectorDock* detector_dock() const { return m_detector_dock; }
    QString status_text() const { return m_status->text(); }
    // Passes done over the pass limit while rendering; hidden otherwise.
    QProgressBar* progress() const { return m_progress; }

    // Adds an object or light of `kind` (sphere, triangle, disc, rectangle, lens, implicit,
    // point, beam) and selects it.
    void add_element(const QString& kind);
    // File ▸ Import lens…: a Zemax .zmx or CODE V .seq file added as a lens_group, resting
    // where the view's centre looks, selected; one undo step. Its millimetres become the
    // scene's units by the scene's `length_unit_mm`; in a scene that declares no unit, a
    // lens larger than the whole scene is offered scaled to fit (`lengths` says what to do
    // without asking). A file that cannot be read leaves the scene as it is; its
    // "FILE:LINE: why" is returned in `error` if given, else shown. The file's warnings (lines
    // passed over) and the scale go to the status line.
    enum class ImportLengths { Ask, Millimetres, FitScene };
    bool import_lens(const QString& path, QString* error = nullptr,
                     ImportLengths lengths = ImportLengths::Ask);
    // A box floor under the scene's objects (Edit ▸ Add floor), selected.
    void add_floor();
    // Edit ▸ Add atmosphere: fog filling the space outside the objects, the declaration's
    // example (scene/medium.h), selected; an atmosphere already there is selected.
    void add_atmosphere();
    void duplicate_selected();
    // The selected object, light or atmosphere.
    void delete_selected();
    // Edit ▸ Optimise lenses…: the dialog for the lenses on the selected lens's axis, shown
    // (it deletes itself when closed); null, with a message, when no lens is selected.
    OptimiseDialog* optimise_selected_lens();
    // Edit ▸ Tolerance lenses…: the dialog for the selected lens's axis; none without a lens.
    ToleranceDialog* tolerance_selected_lens();

protected:
    void closeEvent(QCloseEvent* event) override;

private:
    // The selected lens (a scene object index), or -1 after telling the user to select one:
    // `title` is the action's, `what` says what happens to the lenses on its axis.
    int selected_lens_for(const QString& title, const QString& what);
    void build_menus();
    void update_title();
    void update_recent_menu();
    void remember_recent(const QString& path);
    bool maybe_save();  // asks about unsaved changes; false means "cancel"
    bool save();
    bool save_as();
    void export_image();
    // A message in the status line (the one line: render status and messages share it),
    // for kMessageMs; then the render status comes back.
    void show_message(const QString& text);
    // The render's status ("sppm · rendering (pass 3 of 256) · ..."), shown at once unless a
    // message is up, then when it ends. `error`: in red.
    void set_render_status(const QString& text, bool error = false);
    // Applies an edit of the scene's elements (scene/element_edits.h) as one undo step and
    // selects what it added (nothing, after a removal); false, with the reason shown, if the
    // document refused it.
    bool apply_element_edit(const ElementEdit& edit, const QString& label);
    // The status line: "sppm · rendering (pass 12 of 256) · photons ... · 3.4 s", and the
    // progress bar beside it.
    void show_frame(int passes, qint64 photons, double seconds, const QString& integrator);
    void show_render_end(RenderEnd end, int passes);

    SceneDocument* m_document;
    RenderController* m_renderer;
    SceneTree* m_tree;
    PropertyPanel* m_panel;
    Viewport* m_viewport;
    SectionTab* m_section_tab;  // the section view under its tool bar
    SectionWidget* m_section;
    QTabWidget* m_views;
    RayDiagramDock* m_ray_diagram;
    DetectorDock* m_detector_dock;
    QLabel* m_status;
    QString m_render_status;
    bool m_render_status_error = false;
    bool m_bench_grown = false;      // the bench dock grown once for its figures
    QDeadlineTimer m_message_shown;  // until when a message holds the status line
    QProgressBar* m_progress;
    QString m_integrator, m_frame_figures;  // of the last frame: "sppm", "photons N · 3.4 s"
    QMenu* m_recent_menu = nullptr;
};

}  // namespace lenslab::gui
