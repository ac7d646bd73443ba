#include "main_window.h"

#include <QAction>
#include <QApplication>
#include <QCloseEvent>
#include <QComboBox>
#include <QDir>
#include <QDockWidget>
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
#include "scene/lens_file_import.h"
#include "scene/light_spec.h"
#include "scene/medium.h"
#include "scene/object_types.h"
#include "scene/scene_json.h"
#include "scene_document.h"
#include "scene_tree.h"
#include "section_widget.h"
#include "viewport.h"

namespace lenslab::gui {

namespace {

using nlohmann::json;

constexpr int kMaxRecent = 8;

// The declaration of an element of `list` ("objects", "lights") with this `type`, or null.
const ElementSpec* element_spec(const std::string& list, const std::string& type) {
    if (list == "lights") return find_light_spec(type);
    const ObjectTypeEntry* kind = find_object_type(type);
    return kind ? &kind->spec() : nullptr;
}

// "sphere", or "sphere 2" (3, ...) when an object of the scene has that name already.
std::string unique_name(const json& scene, const std::string& wanted) {
    std::set<std::string> taken;
    if (scene.contains("objects") && scene["objects"].is_array()) {
        for (const json& o : scene["objects"]) {
            if (o.is_object() && o.contains("name") && o["name"].is_string())
                taken.insert(o["name"].get<std::string>());
        }
    }
    std::string name = wanted;
    for (int n = 2; taken.count(name); ++n) name = wanted + " " + std::to_string(n);
    return name;
}

// `element` of `list`, moved by `offset` and named uniquely, ready to append to the scene.
json placed(const json& scene, const std::string& list, json element, const Vec3& offset) {
    if (const ElementSpec* spec = element_spec(list, element.value("type", "")))
        element = moved_element(*spec, std::move(element), offset);
    if (element.contains("name") && element["name"].is_string())
        element["name"] = unique_name(scene, element["name"].get<std::string>());
    return element;
}

// How far `example` (an object as its declaration gives it, or a light) must move so that it
// rests on the surface the view's centre looks at, on the camera's side, touching it with
// its bounding box; a light, or a view of nothing, puts it 3 units ahead of the camera.
// (New objects all landed 3 units ahead, often inside what was there.)
Vec3 placement(const Scene& scene, const json& example) {
    const Vec3 ahead = scene.camera.position + scene.camera.direction * 3.0;
    Scene alone;
    try {
        if (!example.contains("type") || find_light_spec(example["type"].get<std::string>()))
            return ahead;
        alone = scene_from_json(json{{"camera", {{"position", {0, 0, 5}}, {"look_at", {0, 0, 0}}}},
                                     {"objects", json::array({example})}});
    } catch (const std::exception&) {
        return ahead;
    }
    const Aabb box = alone.bounds();
    const Camera camera(scene.camera, scene.render.width, scene.render.height);
    const Ray centre = camera.generate_ray(scene.render.width / 2.0, scene.render.height / 2.0);
    if (box.empty()) return ahead;
    return resting_offset(scene, box, centre).value_or(ahead - box.centre());
}

// A floor: a thin box (one object, not triangles) under everything the scene holds, its top
// where the lowest object ends (y is up, as the camera's default), four times as wide as the
// scene so its edges stay out of most views.
json floor_under(const Scene& scene, const json& document) {
    const Aabb box = scene.bounds();
    const Vec3 centre = box.empty() ? Vec3{0, 0, 0} : box.centre();
    const Vec3 extent = box.empty() ? Vec3{0, 0, 0} : box.extent();
    const double widest = std::max({extent.x, extent.y, extent.z});
    const double side = widest > 0 ? 4 * widest : 10.0;
    const double thickness = side / 100;
    const double top = box.empty() ? 0.0 : box.lo.y;
    return json{{"type", "box"},
                {"name", unique_name(document, "floor")},
                {"center", {centre.x, top - thickness / 2, centre.z}},
                {"size", {side, thickness, side}},
                {"material", {{"color", 0.7}}}};
}

// "Add sphere", "Add lens group", "Add point light": from the declaration's phrase.
QString add_label(const ElementSpec& spec) {
    std::string noun = spec.phrase;
    for (const char* article : {"an ", "a "}) {
        if (noun.rfind(article, 0) == 0) noun = noun.substr(std::strlen(article));
    }
    return QObject::tr("Add %1").arg(QString::fromStdString(noun));
}

}  // namespace

MainWindow::MainWindow(QWidget* parent)
    : QMainWindow(parent),
      m_document(new SceneDocument(this)),
      m_renderer(new RenderController(this)),
      m_tree(new SceneTree(m_document, this)),
      m_panel(new PropertyPanel(m_document, this)),
      m_viewport(new Viewport(m_document, this)),
      m_section(new SectionWidget(m_document, this)),
      m_section_tab(new QWidget(this)),
      m_views(new QTabWidget(this)),
      m_ray_diagram(new RayDiagramDock(m_document, this)),
      m_detector_dock(new DetectorDock(m_document, this)),
      m_status(new QLabel(this)),
      m_progress(new QProgressBar(this)) {
    setObjectName("main_window");
    m_views->setObjectName("views");
    m_views->addTab(m_viewport, tr("3-D view"));
    build_section_tab();
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
    connect(m_section, &SectionWidget::object_picked, this, [this](int object) {
        const int entry = object >= 0 ? m_document->scene().objects[object].source : -1;
        m_tree->select_pointer(entry >= 0 ? join_pointer("/objects", entry) : QString());
    });
    connect(m_section, &SectionWidget::edit_refused, this, &MainWindow::show_message);
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
        m_status->setText(tr("render failed: %1").arg(message));
        m_status->setStyleSheet("color: #c0392b;");
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
         QDir(LENSLAB_SCENES_DIR).entryInfoList({"*.json"}, QDir::Files, QDir::Name)) {
        // Opened as untitled copies: Save must not overwrite the installed example.
        QAction* example =
            examples->addAction(info.baseName(), this, [this, path = info.absoluteFilePath()] {
                if (maybe_save()) open_file(path, nullptr, true);
            });
        example->setObjectName("example:" + info.baseName());
    }
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
    file->addAction(tr("Export &section as SVG..."), this, &MainWindow::export_section_svg)
        ->setObjectName("export_section_svg");
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

    QMenu* render = menuBar()->addMenu(tr("&Render"));
    QAction* start = render->addAction(tr("&Start"), QKeySequence(tr("F5")), this,
                                       [this] { m_renderer->restart(m_document->scene(), 0); });
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

void MainWindow::build_section_tab() {
    auto* plane = new QComboBox(m_section_tab);
    plane->setObjectName("section_plane");
    plane->addItem(tr("Default: the lens's axis, vertical"), int(SectionPlaneChoice::Default));
    plane->addItem(tr("x-y plane"), int(SectionPlaneChoice::XY));
    plane->addItem(tr("y-z plane"), int(SectionPlaneChoice::YZ));
    plane->addItem(tr("z-x plane (seen from above)"), int(SectionPlaneChoice::ZX));
    connect(plane, &QComboBox::currentIndexChanged, this, [this, plane](int index) {
        m_section->set_plane_choice(SectionPlaneChoice(plane->itemData(index).toInt()));
    });
    auto* export_svg = new QPushButton(tr("Export SVG..."), m_section_tab);
    export_svg->setObjectName("section_export_svg");
    connect(export_svg, &QPushButton::clicked, this, &MainWindow::export_section_svg);
    auto* bar = new QHBoxLayout;
    bar->addWidget(new QLabel(tr("Plane:"), m_section_tab));
    bar->addWidget(plane);
    bar->addStretch(1);
    bar->addWidget(export_svg);
    auto* layout = new QVBoxLayout(m_section_tab);
    layout->setContentsMargins(4, 4, 4, 4);
    layout->addLayout(bar);
    layout->addWidget(m_section, 1);
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

void MainWindow::export_section_svg() {
    QString path = QFileDialog::getSaveFileName(this, tr("Export section"), QString(),
                                                tr("SVG pictures (*.svg)"));
    if (path.isEmpty()) return;
    if (QFileInfo(path).suffix().isEmpty()) path += ".svg";
    QString error;
    if (!m_section->export_svg(path, &error))
        QMessageBox::warning(this, tr("Cannot export"), error);
}

void MainWindow::show_message(const QString& text) { statusBar()->showMessage(text, 10000); }

void MainWindow::show_frame(int passes, qint64 photons, double seconds, const QString& integrator) {
    const int limit = m_renderer->max_passes();
    m_integrator = integrator;
    m_frame_figures = tr("photons %1 · %2 s").arg(photons).arg(seconds, 0, 'f', 1);
    m_status->setStyleSheet({});
    m_status->setText(tr("%1 · rendering (pass %2 of %3) · %4")
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
    m_status->setText(tr("%1 · %2 · %3").arg(m_integrator, state, m_frame_figures));
}

bool MainWindow::open_file(const QString& path, QString* error, bool as_copy) {
    QString message;
    if (!m_document->open(path, &message, as_copy)) {
        if (error)
            *error = message;
        else
            show_open_error(message);
        show_message(message);
        return false;
    }
    if (!as_copy) remember_recent(path);
    m_tree->select_pointer("/camera");
    return true;
}

void MainWindow::show_open_error(const QString& message) {
    auto* box = new QMessageBox(QMessageBox::Warning, tr("Cannot open scene"), message,
                                QMessageBox::Ok, this);
    box->setObjectName("open_error");
    box->setAttribute(Qt::WA_DeleteOnClose);
    box->open();
}

bool MainWindow::save_file(const QString& path, QString* error) {
    QString message;
    if (!m_document->save(path, &message)) {
        if (error)
            *error = message;
        else
            QMessageBox::warning(this, tr("Cannot save"), message);
        return false;
    }
    remember_recent(path);
    return true;
}

bool MainWindow::save() {
    return m_document->path().isEmpty() ? save_as() : save_file(m_document->path());
}

bool MainWindow::save_as() {
    const QString path = QFileDialog::getSaveFileName(this, tr("Save scene"), m_document->path(),
                                                      tr("Scenes (*.json)"));
    return !path.isEmpty() && save_file(path);
}

bool MainWindow::maybe_save() {
    if (!m_document->is_modified()) return true;
    const auto answer =
        QMessageBox::question(this, tr("Unsaved changes"), tr("Save the changes to this scene?"),
                              QMessageBox::Save | QMessageBox::Discard | QMessageBox::Cancel);
    if (answer == QMessageBox::Save) return save();
    return answer == QMessageBox::Discard;
}

void MainWindow::closeEvent(QCloseEvent* event) {
    if (maybe_save()) {
        QSettings("lenslab", "lenslab-gui").setValue("geometry", saveGeometry());
        m_renderer->stop_rendering();
        event->accept();
    } else {
        event->ignore();
    }
}

void MainWindow::export_image() {
    const QString path = QFileDialog::getSaveFileName(this, tr("Export image"), "lenslab.png",
                                                      tr("Images (*.png *.exr)"));
    if (!path.isEmpty()) export_image_to(path);
}

bool MainWindow::export_image_to(const QString& path, QString* error) {
    // The view's render waits meanwhile (the export gets every core) and then goes on.
    m_renderer->set_paused(true);
    QString message;
    const bool written = export_scene_image(m_document->scene(), path, this, &message);
    m_renderer->set_paused(false);
    if (!written) {
        if (error)
            *error = message;
        else
            QMessageBox::warning(this, tr("Cannot export"), message);
        show_message(message);
        return false;
    }
    show_message(tr("wrote %1").arg(path));
    return true;
}

void MainWindow::remember_recent(const QString& path) {
    QSettings settings("lenslab", "lenslab-gui");
    QStringList recent = settings.value("recent").toStringList();
    recent.removeAll(QFileInfo(path).absoluteFilePath());
    recent.prepend(QFileInfo(path).absoluteFilePath());
    while (recent.size() > kMaxRecent) recent.removeLast();
    settings.setValue("recent", recent);
    update_recent_menu();
}

void MainWindow::update_recent_menu() {
    m_recent_menu->clear();
    for (const QString& path : QSettings("lenslab", "lenslab-gui").value("recent").toStringList()) {
        m_recent_menu->addAction(path, this, [this, path] {
            if (maybe_save()) open_file(path);
        });
    }
    m_recent_menu->setEnabled(!m_recent_menu->isEmpty());
}

void MainWindow::add_element(const QString& kind) {
    json edited = m_document->json();
    const std::string type = kind.toStdString();
    const std::string list = find_light_spec(type) ? "lights" : "objects";
    const ElementSpec* spec = element_spec(list, type);
    if (!spec) return;
    if (!edited.contains(list)) edited[list] = json::array();
    edited[list].push_back(
        placed(edited, list, spec->example, placement(m_document->scene(), spec->example)));
    QString error;
    if (!m_document->apply(edited, tr("Add %1").arg(kind), &error)) {
        show_message(error);
        return;
    }
    const qsizetype index = qsizetype(edited[list].size() - 1);
    m_tree->select_pointer(join_pointer(join_pointer("", QString::fromStdString(list)), index));
    if (list == "objects") {
        // It rests where the view's centre looks; the next click in the view moves it there.
        m_viewport->arm_placement(int(index));
        show_message(
            tr("Click in the 3-D view to place the new %1 (Esc: leave it here).").arg(kind));
    }
}

bool MainWindow::import_lens(const QString& path, QString* error) {
    const std::string file = path.toStdString();
    ImportedLens lens;
    try {
        lens = import_lens_file(file, QFileInfo(path).completeBaseName().toStdString());
    } catch (const std::exception& e) {
        if (error) {
            *error = QString::fromStdString(e.what());
        } else {
            QMessageBox::warning(this, tr("Import lens"), QString::fromStdString(e.what()));
        }
        return false;
    }
    json edited = m_document->json();
    if (!edited.contains("objects")) edited["objects"] = json::array();
    // The lens_group as `lenslab import` writes it (vertex at the origin, along +z).
    const json group = json::parse(imported_scene_json(lens, file)["objects"][0].dump());
    edited["objects"].push_back(
        placed(edited, "objects", group, placement(m_document->scene(), group)));
    QString why;
    if (!m_document->apply(edited, tr("Import lens"), &why)) {
        if (error) {
            *error = why;
        } else {
            show_message(why);
        }
        return false;
    }
    m_tree->select_pointer(join_pointer("/objects", qsizetype(edited["objects"].size() - 1)));
    QString note = tr("Imported %1: %2 element(s), lengths in mm")
                       .arg(QFileInfo(path).fileName())
                       .arg(lens.element_lines.size());
    const double unit_mm = edited.value("length_unit_mm", 1.0);
    if (unit_mm != 1.0) note += tr(" (the scene's unit is %1 mm)").arg(unit_mm);
    if (!lens.warnings.empty())
        note += tr("; %1 line(s) passed over: %2")
                    .arg(lens.warnings.size())
                    .arg(QString::fromStdString(lens_file_warnings_text(lens, file)).trimmed());
    show_message(note);
    return true;
}

void MainWindow::add_floor() {
    json edited = m_document->json();
    if (!edited.contains("objects")) edited["objects"] = json::array();
    edited["objects"].push_back(floor_under(m_document->scene(), edited));
    QString error;
    if (!m_document->apply(edited, tr("Add floor"), &error)) {
        show_message(error);
        return;
    }
    m_tree->select_pointer(join_pointer("/objects", qsizetype(edited["objects"].size() - 1)));
}

void MainWindow::add_atmosphere() {
    if (!m_document->json().contains("atmosphere")) {
        json edited = m_document->json();
        edited["atmosphere"] = medium_spec().example;
        QString error;
        if (!m_document->apply(edited, tr("Add atmosphere"), &error)) {
            show_message(error);
            return;
        }
    }
    m_tree->select_pointer("/atmosphere");
}

void MainWindow::duplicate_selected() {
    const QString pointer = m_tree->selected_pointer();
    if (!pointer.startsWith("/objects/") && !pointer.startsWith("/lights/")) return;
    json edited = m_document->json();
    const std::string list = split_pointer(pointer)[0].toStdString();
    json copy = edited[json::json_pointer(pointer.toStdString())];
    if (copy.contains("name") && copy["name"].is_string())
        copy["name"] = copy["name"].get<std::string>() + " copy";
    edited[list].push_back(placed(edited, list, std::move(copy), Vec3{0.5, 0, 0}));
    QString error;
    if (!m_document->apply(edited, tr("Duplicate"), &error)) {
        show_message(error);
        return;
    }
    m_tree->select_pointer(join_pointer(join_pointer("", QString::fromStdString(list)),
                                        qsizetype(edited[list].size() - 1)));
}

void MainWindow::delete_selected() {
    const QString pointer = m_tree->selected_pointer();
    json edited = m_document->json();
    if (pointer == "/atmosphere") {
        edited.erase("atmosphere");
    } else if (pointer.startsWith("/objects/") || pointer.startsWith("/lights/")) {
        const QStringList tokens = split_pointer(pointer);  // {"objects", "3"}
        edited[tokens[0].toStdString()].erase(size_t(tokens[1].toInt()));
    } else {
        return;
    }
    QString error;
    if (!m_document->apply(edited, tr("Delete"), &error)) {
        show_message(error);
        return;
    }
    m_tree->select_pointer(QString());
    m_panel->show_pointer(QString());
}

OptimiseDialog* MainWindow::optimise_selected_lens() {
    if (m_ray_diagram->lens() < 0) {
        QMessageBox::information(this, tr("Optimise lenses"),
                                 tr("Select a lens: the lenses on its axis are optimised."));
        return nullptr;
    }
    auto* dialog = new OptimiseDialog(m_document, m_ray_diagram->lens(), this);
    dialog->setAttribute(Qt::WA_DeleteOnClose);
    // Modal: an edit made during the run would be lost when its result is applied.
    dialog->setModal(true);
    dialog->set_choices(m_ray_diagram->optimise_defaults());
    dialog->show();
    return dialog;
}

}  // namespace lenslab::gui
