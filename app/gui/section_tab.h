#pragma once
// The Section tab: the section view under its tool bar (plane, rays per source, fit all,
// fit selection, the tools: move, ruler, protractor; export) with the read-out of a clicked
// ray or a measurement beside it.

#include <QWidget>

class QPlainTextEdit;

namespace lenslab::gui {

class SceneDocument;
class SectionWidget;

class SectionTab : public QWidget {
    Q_OBJECT

public:
    explicit SectionTab(SceneDocument* document, QWidget* parent = nullptr);

    SectionWidget* view() const { return m_view; }
    // Asks for a file and writes the view there: SVG (the drawing) or PNG (as it shows).
    void export_view();

signals:
    void message(const QString& text);

private:
    SectionWidget* m_view;
    QPlainTextEdit* m_readout;  // the clicked ray's path or the last measurement
};

}  // namespace lenslab::gui
