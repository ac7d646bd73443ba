#include "main_window.h"

#include <QAction>
#include <QApplication>
#include <QCloseEvent>
#include <QComboBox>
#include <QDir>
#include <QDockWidget>
#include <QFile>
#include <QFileDialog>
#include <QFileInfo>
#include <QHBoxLayout>
#include <QMenuBar>
#include <QMessageBox>
#include <QPushButton>
#include <QScreen>
#include <QScrollArea>
#include <QSettings>
#include <QStatusBar>
#include <QTabWidget>
#include <QToolBar>
#include <QToolButton>
#include <QVBoxLayout>
#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <set>
#include <string>
#include <vector>

#include "detector_dock.h"
#include "image/image_io.h"
#include "image_export.h"
#include "json_pointer.h"
#include "optimise_dialog.h"
#include "placement.h"
#include "property_panel.h"
#include "ray_diagram_dock.h"
#include "render/camera.h"
#include "render_controller.h"
#include "scene/element_edits.h"
#include "scene/lens_file_import.h"
#include "scene/light_spec.h"
#include "scene/medium.h"
#include "scene/object_types.h"
#include "scene/scene_json.h"
#include "scene_document.h"
#include "scene_tree.h"
#include "section_tab.h"
#include "section_widget.h"
#include "tolerance_dialog.h"
#include "viewport.h"

namespace lenslab::gui {

namespace {

using nlohmann::json;

// "Add sphere", "Add lens group", "Add point light": from the declaration's phrase.
QString add_label(const ElementSpec& spec) {
    std::string noun = spec.phrase;
    for (const char* article : {"an ", "a "}) {
        if (noun.rfind(article, 0) == 0) noun = noun.substr(std::strlen(article));
    }
    return QObject::tr("Add %1").arg(QString::fromStdString(noun));
}

// The example scenes: the source tree's in a build, else where `cmake --install` put them
// (the source path was compiled in, and an installed editor had no examples without it).
QString examples_folder() {
    for (const char* dir : {LENSLAB_SCENES_SOURCE, LENSLAB_SCENES_INSTALL}) {
        if (QDir(dir).exists("default.json")) return dir;
    }
    return LENSLAB_SCENES_INSTALL;
}

// A scene file's `description`, or empty (unreadable, or none): the examples' tooltips.
QString scene_description(const QString& path) {
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly)) return {};
    const json j = json::parse(file.readAll().toStdString(), nullptr, false);
    if (!j.is_object() || !j.contains("description") || !j["description"].is_string()) return {};
    return QString::fromStdString(j["description"].get<std::string>());
}

}  // namespace

MainWindow::MainWindow(QWidget* parent)
    : QMainWindow(parent),
      m_document(new SceneDocument(this)),
      m_renderer(new RenderController(this)),
      m_tree(new SceneTree(m_document, this)),
      m_panel(new PropertyPanel(m_document, this)),
      m_viewport(new Viewport(m_document, this)),
      m_section_tab(new SectionTab(m_document, this)),
      m_section(m_section_tab->view()),
      m_views(new QTabWidget(this)),
      m_ray_diagram(new RayDiagramDock(m_document, this)),
      m_detector_dock(new DetectorDock(m_document, this)),
      m_status(new QLabel(this)),
      m_progress(new QProgressBar(this)) {
    setObjectName("main_window");
    m_views->setObjectName("views");
    m_views->addTab(m_viewport, tr("3-D view"));
    m_views->addTab(m_section_tab, tr("Section"));
    setCentralWidget(m_views);

    auto* tree_dock = new QDockWidget(tr("Scene"), this);
    tree_dock->setObjectName("scene_dock");
    tree_dock->setWidget(m_tree);
    addDockWidget(Qt::LeftDockWidgetArea, tree_dock);
    auto* scroll = new QScrollArea(this);
    scroll->setWidget(m_panel);
    scroll->setWidgetResizable(true);
    scroll->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
    auto* panel_dock = new QDockWidget(tr("Properties"), this);
    panel_dock->setObjectName("properties_dock");
    panel_dock->setWidget(scroll);
    addDockWidget(Qt::RightDockWidgetArea, panel_dock);
    addDockWidget(Qt::BottomDockWidgetArea, m_ray_diagram);
    addDockWidget(Qt::RightDockWidgetArea, m_detector_dock);
    tabifyDockWidget(panel_dock, m_detector_dock);
    panel_dock->raise();
    statusBar()->addWidget(m_status, 1);
    m_status->setObjectName("render_status");
    m_progress->setObjectName("render_progress");
    m_progress->setMaximumWidth(160);
    m_progress->setTextVisible(false);
    m_progress->hide();
    statusBar()->addPermanentWidget(m_progress);

    connect(m_tree, &SceneTree::pointer_selected, m_panel, &PropertyPanel::show_pointer);
    connect(m_tree, &SceneTree::pointer_selected, m_ray_diagram, &RayDiagramDock::show_pointer);
    connect(m_tree, &SceneTree::pointer_selected, m_detector_dock, &DetectorDock::show_pointer);
    connect(m_tree, &SceneTree::pointer_selected, m_section, &SectionWidget::show_pointer);
    connect(m_tree, &SceneTree::pointer_selected, m_viewport, &Viewport::show_pointer);
    // The first figure asked for (spots, fans, ...) gets the room to show at a readable size:
    // the dock grows to 45% of the window once; later sizes are the user's.
    connect(m_ray_diagram->tabs(), &QTabWidget::currentChanged, this, [this](int tab) {
        const int room = height() * 45 / 100;
        if (tab == 0 || m_bench_grown || m_ray_diagram->height() >= room) return;
        m_bench_grown = true;
        resizeDocks({m_ray_diagram}, {room}, Qt::Vertical);
    });
    connect(m_section, &SectionWidget::object_picked, this, [this](int object) {
        const int entry = object >= 0 ? m_document->scene().objects[object].source : -1;
        m_tree->select_pointer(entry >= 0 ? join_pointer("/objects", entry) : QString());
    });
    connect(m_section, &SectionWidget::edit_refused, this, &MainWindow::show_message);
    connect(m_section_tab, &SectionTab::message, this, &MainWindow::show_message);
    connect(m_viewport, &Viewport::object_picked, this, [this](int object) {
        m_tree->select_pointer(object >= 0 ? join_pointer("/objects", object) : QString());
    });
    connect(m_viewport, &Viewport::light_picked, this,
            [this](int light) { m_tree->select_pointer(join_pointer("/lights", light)); });
    // A drag ended (perhaps where it began, changing nothing): the full render at once.
    connect(m_viewport, &Viewport::interaction_finished, this,
            [this] { m_renderer->restart(m_document->scene(), 0); });
    connect(m_panel, &PropertyPanel::edit_refused, this, &MainWindow::show_message);
    connect(m_panel, &PropertyPanel::pointer_requested, m_tree, &SceneTree::select_pointer);
    connect(m_panel, &PropertyPanel::delete_requested, this, &MainWindow::delete_selected);
    connect(m_viewport, &Viewport::edit_refused, this, &MainWindow::show_message);
    connect(m_document, &SceneDocument::changed, this, [this] {
        // While the view or the section is dragged, a coarse frame at once for every step.
        if (m_viewport->is_interacting() || m_section->is_dragging())
            m_renderer->restart(m_document->scene(), 0, RenderQuality::Draft);
        else
            m_renderer->restart(m_document->scene());
        update_title();
    });
    connect(m_document->undo_stack(), &QUndoStack::cleanChanged, this, &MainWindow::update_title);
    connect(m_document, &SceneDocument::path_changed, this, &MainWindow::update_title);
    connect(m_renderer, &RenderController::frame_ready, this,
            [this](const QImage& image, int passes, qint64 photons, double seconds,
                   const QString& integrator) {
                m_viewport->set_image(image);
                show_frame(passes, photons, seconds, integrator);
            });
    connect(m_renderer, &RenderController::preview_ready, m_viewport, &Viewport::set_image);
    connect(m_renderer, &RenderController::render_ended, this, &MainWindow::show_render_end);
    // A refused render keeps its reason in the status line until the next frame (a message
    // there would time out and bring the old status back, as if nothing had failed).
    connect(m_renderer, &RenderController::render_failed, this, [this](const QString& message) {
        set_render_status(tr("render failed: %1").arg(message), true);
        m_progress->hide();
    });

    build_menus();
    // The size it had when last closed, else 1280 x 800 or what the screen has room for.
    if (!restoreGeometry(QSettings("lenslab", "lenslab-gui").value("geometry").toByteArray())) {
        const QRect room = screen()->availableGeometry();
        resize(std::min(1280, room.width() * 9 / 10), std::min(800, room.height() * 9 / 10));
    }
    resizeDocks({tree_dock, panel_dock}, {230, 420}, Qt::Horizontal);
    update_title();
    m_tree->select_pointer("/camera");
    m_renderer->restart(m_document->scene(), 0);
}

MainWindow::~MainWindow() {
    // The document and its undo stack are children, destroyed after this object has become a
    // plain QWidget; signals they send while going (the undo stack's cleanChanged) must not
    // reach MainWindow's slots then (UBSan: downcast to a destroyed MainWindow).
    m_document->undo_stack()->disconnect(this);
    m_document->disconnect(this);
}

void MainWindow::build_menus() {
    QMenu* file = menuBar()->addMenu(tr("&File"));
    file->addAction(tr("&New (default scene)"), this, [this] {
        if (maybe_save()) m_document->load_default();
    });
    file->addAction(tr("&Open..."), QKeySequence::Open, this, [this] {
        if (!maybe_save()) return;
        const QString path =
            QFileDialog::getOpenFileName(this, tr("Open scene"), QString(), tr("Scenes (*.json)"));
        if (!path.isEmpty()) open_file(path);
    });
    QMenu* examples = file->addMenu(tr("Open &example"));
    for (const QFileInfo& info :
         QDir(examples_folder()).entryInfoList({"*.json"}, QDir::Files, QDir::Name)) {
        // Opened as untitled copies: Save must not overwrite the installed example.
        QAction* example =
            examples->addAction(info.baseName(), this, [this, path = info.absoluteFilePath()] {
                if (maybe_save()) open_file(path, nullptr, true);
            });
        example->setObjectName("example:" + info.baseName());
        // Rich text, so a long description wraps.
        const QString about = scene_description(info.absoluteFilePath());
        if (!about.isEmpty()) example->setToolTip("<p>" + about.toHtmlEscaped() + "</p>");
    }
    examples->setToolTipsVisible(true);
    m_recent_menu = file->addMenu(tr("Open &recent"));
    update_recent_menu();
    file->addSeparator();
    file->addAction(tr("&Save"), QKeySequence::Save, this, [this] { save(); });
    // Spelled out: QKeySequence::SaveAs is empty on X11.
    file->addAction(tr("Save &as..."), QKeySequence(tr("Ctrl+Shift+S")), this,
                    [this] { save_as(); })
        ->setObjectName("save_as");
    file->addAction(tr("&Import lens..."), QKeySequence(tr("Ctrl+I")), this,
                    [this] {
                        const QString path = QFileDialog::getOpenFileName(
                            this, tr("Import lens"), QString(),
                            tr("Lens files (*.zmx *.ZMX *.zar *.ZAR *.seq *.SEQ);;All files (*)"));
                        if (!path.isEmpty()) import_lens(path);
                    })
        ->setObjectName("import_lens");
    file->addAction(tr("&Export image..."), QKeySequence(tr("Ctrl+E")), this,
                    &MainWindow::export_image)
        ->setObjectName("export_image");
    file->addAction(tr("Export &section..."), m_section_tab, &SectionTab::export_view)
        ->setObjectName("export_section");
    file->addSeparator();
    file->addAction(tr("&Quit"), QKeySequence::Quit, this, &QWidget::close);

    QMenu* edit = menuBar()->addMenu(tr("&Edit"));
    QAction* undo = m_document->undo_stack()->createUndoAction(this, tr("&Undo"));
    undo->setShortcut(QKeySequence::Undo);
    QAction* redo = m_document->undo_stack()->createRedoAction(this, tr("&Redo"));
    redo->setShortcut(QKeySequence::Redo);
    edit->addAction(undo);
    edit->addAction(redo);
    edit->addSeparator();
    QToolBar* tools = addToolBar(tr("Edit"));
    tools->setObjectName("edit_toolbar");
    // One action per declared type, each adding the declaration's example; on the toolbar
    // they drop down from two buttons, objects and lights, so the bar fits a laptop screen.
    std::vector<const ElementSpec*> objects;
    for (const ObjectTypeEntry& t : object_types()) objects.push_back(&t.spec());
    const auto add_menu = [&](const QString& title, const QString& name,
                              const std::vector<const ElementSpec*>& specs) {
        auto* menu = new QMenu(title, this);
        for (const ElementSpec* spec : specs) {
            const QString kind =
                QString::fromStdString(spec->example.at("type").get<std::string>());
            QAction* a =
                edit->addAction(add_label(*spec), this, [this, kind] { add_element(kind); });
            a->setObjectName("add:" + kind);
            menu->addAction(a);
        }
        auto* button = new QToolButton(tools);
        button->setObjectName(name);
        button->setText(title);
        button->setMenu(menu);
        button->setPopupMode(QToolButton::InstantPopup);
        tools->addWidget(button);
    };
    add_menu(tr("Add object"), "add_object_button", objects);
    add_menu(tr("Add light"), "add_light_button", light_specs());
    QAction* floor = edit->addAction(tr("Add &floor"), this, &MainWindow::add_floor);
    floor->setObjectName("add_floor");  // not a declared type (those are "add:TYPE")
    tools->addAction(floor);
    edit->addAction(tr("Add &atmosphere"), this, &MainWindow::add_atmosphere)
        ->setObjectName("add_atmosphere");
    edit->addAction(tr("&Duplicate"), QKeySequence(tr("Ctrl+D")), this,
                    &MainWindow::duplicate_selected);
    edit->addAction(tr("De&lete"), QKeySequence::Delete, this, &MainWindow::delete_selected);
    edit->addSeparator();
    edit->addAction(tr("&Optimise lenses..."), this, &MainWindow::optimise_selected_lens)
        ->setObjectName("optimise_lenses");
    edit->addAction(tr("&Tolerance lenses..."), this, &MainWindow::tolerance_selected_lens)
        ->setObjectName("tolerance_lenses");

    QMenu* render = menuBar()->addMenu(tr("&Render"));
    // Start goes on from where Stop left the same scene; a changed scene starts afresh.
    QAction* start = render->addAction(tr("&Start"), QKeySequence(tr("F5")), this, [this] {
        if (!m_renderer->resume()) m_renderer->restart(m_document->scene(), 0);
    });
    start->setObjectName("render_start");
    QAction* stop = render->addAction(tr("S&top"), QKeySequence(tr("Shift+F5")), this,
                                      [this] { m_renderer->stop_rendering(); });
    stop->setObjectName("render_stop");
    render->addSeparator();
    // The view renders with sppm, which converges to the full light transport; the scene's
    // own integrator (what `lenslab render` uses) is one click away.
    QAction* own = render->addAction(tr("View with the scene's &integrator"));
    own->setObjectName("view_with_scene_integrator");
    own->setCheckable(true);
    own->setChecked(m_renderer->uses_scene_integrator());
    connect(own, &QAction::toggled, this, [this](bool on) {
        m_renderer->set_use_scene_integrator(on);
        m_renderer->restart(m_document->scene(), 0);
    });
    tools->addSeparator();
    tools->addAction(start);
    tools->addAction(stop);
}

void MainWindow::update_title() {
    QString name = tr("default scene");
    if (!m_document->path().isEmpty())
        name = QFileInfo(m_document->path()).fileName();
    else if (!m_document->copied_from().isEmpty())
        name = tr("%1 (example, not saved)").arg(QFileInfo(m_document->copied_from()).fileName());
    setWindowTitle(QString("%1%2 — lenslab").arg(name, m_document->is_modified() ? " *" : ""));
}

bool MainWindow::show_view(const QString& name) {
    if (name == "3d") {
        m_views->setCurrentWidget(m_viewport);
    } else if (name == "section") {
        m_views->setCurrentWidget(m_section_tab);
    } else {
        return false;
    }
    return true;
}

namespace {

// How long a message holds the status line before the render status comes back.
constexpr int kMessageMs = 5000;

}  // namespace

void MainWindow::show_message(const QString& text) {
    m_message_shown = QDeadlineTimer(kMessageMs);
    m_status->setStyleSheet({});
    m_status->setText(text);
    QTimer::singleShot(kMessageMs, this, [this] {
        if (m_message_shown.hasExpired()) set_render_status(m_render_status, m_render_status_error);
    });
}

void MainWindow::set_render_status(const QString& text, bool error) {
    m_render_status = text;
    m_render_status_error = error;
    if (!m_message_shown.hasExpired()) return;
    m_status->setStyleSheet(error ? "color: #c0392b;" : "");
    m_status->setText(text);
}

void MainWindow::show_frame(int passes, qint64 photons, double seconds, const QString& integrator) {
    const int limit = m_renderer->max_passes();
    m_integrator = integrator;
    m_frame_figures = tr("photons %1 · %2 s").arg(photons).arg(seconds, 0, 'f', 1);
    set_render_status(tr("%1 · rendering (pass %2 of %3) · %4")
                          .arg(integrator)
                          .arg(passes)
                          .arg(limit)
                          .arg(m_frame_figures));
    m_progress->setRange(0, limit);
    m_progress->setValue(passes);
    m_progress->show();
}

void MainWindow::show_render_end(RenderEnd end, int passes) {
    if (end == RenderEnd::Failed || end == RenderEnd::Restarted) return;
    m_progress->hide();
    if (passes == 0) return;
    const QString state =
        end == RenderEnd::Converged
            ? tr("converged (%1 passes)").arg(passes)
            : tr("stopped at pass %1 of %2").arg(passes).arg(m_renderer->max_passes());
    set_render_status(tr("%1 · %2 · %3").arg(m_integrator, state, m_frame_figures));
}

int MainWindow::selected_lens_for(const QString& title, const QString& what) {
    const int lens = m_ray_diagram->lens();
    if (lens < 0) {
        QMessageBox::information(this, title,
                                 tr("Select a lens: the lenses on its axis are %1.").arg(what));
    }
    return lens;
}

OptimiseDialog* MainWindow::optimise_selected_lens() {
    const int lens = selected_lens_for(tr("Optimise lenses"), tr("optimised"));
    if (lens < 0) return nullptr;
    auto* dialog = new OptimiseDialog(m_document, lens, this);
    dialog->setAttribute(Qt::WA_DeleteOnClose);
    // Modal: an edit made during the run would be lost when its result is applied.
    dialog->setModal(true);
    dialog->set_choices(m_ray_diagram->optimise_defaults());
    dialog->show();
    return dialog;
}

ToleranceDialog* MainWindow::tolerance_selected_lens() {
    const int lens = selected_lens_for(tr("Tolerance lenses"), tr("toleranced"));
    if (lens < 0) return nullptr;
    auto* dialog = new ToleranceDialog(m_document, lens, this);
    dialog->setAttribute(Qt::WA_DeleteOnClose);
    ToleranceChoices choices;
    choices.optics = m_ray_diagram->optimise_defaults();
    dialog->set_choices(choices);
    dialog->show();
    return dialog;
}

}  // namespace lenslab::gui
