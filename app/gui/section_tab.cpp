#include "section_tab.h"

#include <QButtonGroup>
#include <QComboBox>
#include <QFileDialog>
#include <QFileInfo>
#include <QPlainTextEdit>
#include <QSpinBox>
#include <QToolBar>
#include <QToolButton>
#include <QVBoxLayout>

#include "section_widget.h"

namespace lenslab::gui {

namespace {

// The most rays per source the spin box offers: a beam of 1,000 still redraws at 60 frames
// per second (docs/performance.md).
constexpr int kMostSectionRays = 1000;
// Lines of the read-out shown at once (a ray's path through a lens onto a screen); longer
// ones scroll.
constexpr int kReadoutLines = 3;

}  // namespace

SectionTab::SectionTab(SceneDocument* document, QWidget* parent)
    : QWidget(parent),
      m_view(new SectionWidget(document, this)),
      m_readout(new QPlainTextEdit(this)) {
    auto* plane = new QComboBox(this);
    plane->setObjectName("section_plane");
    plane->setToolTip(
        tr("The plane shown: through the selected lens's axis (upright), or a "
           "plane of the scene's axes through the selection"));
    plane->addItem(tr("Lens's axis"), int(SectionPlaneChoice::Default));
    plane->addItem(tr("x-y plane"), int(SectionPlaneChoice::XY));
    plane->addItem(tr("y-z plane"), int(SectionPlaneChoice::YZ));
    plane->addItem(tr("z-x (top)"), int(SectionPlaneChoice::ZX));
    connect(plane, &QComboBox::currentIndexChanged, this, [this, plane](int index) {
        m_view->set_plane_choice(SectionPlaneChoice(plane->itemData(index).toInt()));
    });
    auto* rays = new QSpinBox(this);
    rays->setObjectName("section_rays");
    rays->setRange(1, kMostSectionRays);
    rays->setValue(m_view->rays());
    rays->setToolTip(tr("Rays across the selection's beam and in each light's fan"));
    connect(rays, &QSpinBox::valueChanged, m_view, &SectionWidget::set_rays);

    rays->setPrefix(tr("Rays: "));
    auto* fit_all = new QToolButton(this);
    fit_all->setText(tr("Fit all"));
    fit_all->setObjectName("section_fit_all");
    connect(fit_all, &QToolButton::clicked, m_view, &SectionWidget::fit_all);
    auto* fit_selection = new QToolButton(this);
    fit_selection->setText(tr("Fit selection"));
    fit_selection->setObjectName("section_fit_selection");
    connect(fit_selection, &QToolButton::clicked, m_view, &SectionWidget::fit_selection);

    // The tools, one checked at a time.
    auto* tools = new QButtonGroup(this);
    const struct {
        SectionTool tool;
        const char *name, *text, *tip;
    } kinds[] = {
        {SectionTool::Move, "section_tool_move", "Move",
         "Drag an object to move it (with Shift to turn it), empty paper to pan; click a ray "
         "to read its angles"},
        {SectionTool::Ruler, "section_tool_ruler", "Ruler", "Drag to measure a length"},
        {SectionTool::Protractor, "section_tool_protractor", "Protractor",
         "Click two rays or surfaces: the angle between them"},
    };
    // A tool bar: what does not fit a narrow window folds into its extension menu, so the
    // window still fits a small or scaled screen.
    auto* bar = new QToolBar(this);
    bar->setObjectName("section_tool_bar");
    bar->setMovable(false);  // in the tab's layout, not a main window's: no handle to drag
    bar->addWidget(plane);
    bar->addWidget(rays);
    bar->addWidget(fit_all);
    bar->addWidget(fit_selection);
    for (const auto& kind : kinds) {
        auto* button = new QToolButton(this);
        button->setObjectName(kind.name);
        button->setText(tr(kind.text));
        button->setToolTip(tr(kind.tip));
        button->setCheckable(true);
        button->setChecked(kind.tool == SectionTool::Move);
        tools->addButton(button, int(kind.tool));
        bar->addWidget(button);
    }
    connect(tools, &QButtonGroup::idClicked, this, [this](int id) {
        m_view->set_tool(SectionTool(id));
        if (SectionTool(id) != SectionTool::Move) m_readout->clear();
    });
    auto* export_button = new QToolButton(this);
    export_button->setText(tr("Export..."));
    export_button->setObjectName("section_export");
    export_button->setToolTip(tr("The drawing as SVG, or the view as it shows as PNG"));
    connect(export_button, &QToolButton::clicked, this, &SectionTab::export_view);
    bar->addWidget(export_button);

    // Read-only text (to copy into notes) of a fixed height: the view keeps its size, and so
    // its scale, when a reading appears in the middle of a drag.
    m_readout->setObjectName("section_readout");
    m_readout->setReadOnly(true);
    m_readout->setFixedHeight(m_readout->fontMetrics().lineSpacing() * kReadoutLines + 10);
    m_readout->setPlaceholderText(
        tr("Click a ray to read its angles at every surface; the Ruler and the Protractor "
           "measure the drawing."));
    connect(m_view, &SectionWidget::ray_inspected, m_readout, &QPlainTextEdit::setPlainText);
    connect(m_view, &SectionWidget::measured, m_readout, &QPlainTextEdit::setPlainText);

    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(4, 4, 4, 4);
    layout->addWidget(bar);
    layout->addWidget(m_view, 1);
    layout->addWidget(m_readout);
}

void SectionTab::export_view() {
    QString path = QFileDialog::getSaveFileName(this, tr("Export section"), QString(),
                                                tr("SVG drawing (*.svg);;PNG picture (*.png)"));
    if (path.isEmpty()) return;
    if (QFileInfo(path).suffix().isEmpty()) path += ".svg";
    QString error;
    const bool png = QFileInfo(path).suffix().compare("png", Qt::CaseInsensitive) == 0;
    if (png ? m_view->export_png(path, &error) : m_view->export_svg(path, &error)) {
        emit message(tr("Wrote %1").arg(path));
    } else {
        emit message(error);
    }
}

}  // namespace lenslab::gui
