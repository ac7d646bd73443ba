#pragma once
// A number field that never lies: it commits exactly the number it shows, or refuses the text
// visibly (red, the reason in its tooltip) and keeps the last good value. It reads what a
// person writes: a leading minus, scientific notation ("-12e-1"), and the declared unit after
// the number ("30 deg") where the parameter has one; anything else after the number ("-1,2",
// "1.5mm" for a unitless length) is refused rather than stripped. The declared range is
// checked with the declaration's own words. The wheel acts only on a focused field, in steps
// of the value's second significant digit. Numbers show with up to 6 significant digits.
// Escape gives up an edit: the field shows its last good value again.

#include <QLineEdit>
#include <optional>
#include <string>

#include "scene/param_spec.h"

namespace lenslab::gui {

// `text` read as a number for `p` (its unit, whole-number kind and range), or why not.
struct ParsedNumber {
    std::optional<double> value;
    QString problem;  // empty when `value` holds
};
ParsedNumber parse_number(const QString& text, const ParamSpec& p);

// How a value shows: up to 6 significant digits, no trailing zeros ("0.06", "-20", "1e-09").
QString format_shown(double v);

class NumberField : public QLineEdit {
    Q_OBJECT

public:
    // `p` gives the range, unit, kind (whole or not) and documentation.
    NumberField(const ParamSpec& p, QWidget* parent = nullptr);

    double value() const { return m_value; }
    // Shows `v` as the last good value (no signal).
    void setValue(double v);
    // The declared ends (infinite where open); whether each is exclusive is in the spec.
    double minimum() const;
    double maximum() const;
    const ParamSpec& spec() const { return m_spec; }
    // Why the text now shown was refused, or empty.
    const QString& problem() const { return m_problem; }

signals:
    // A new value the person wrote (or wheeled to); the field already shows it.
    void committed(double value);
    // The text was refused for `reason`; the field keeps its last good value.
    void refused(const QString& reason);
    // A refusal it showed no longer applies: a good value shows again (typed, or Escape).
    void problem_cleared();

protected:
    void wheelEvent(QWheelEvent* event) override;
    // Escape puts the last good value back (and clears a refusal), committing nothing.
    void keyPressEvent(QKeyEvent* event) override;

private:
    void finish_editing();
    void show_problem(const QString& reason);
    QString documentation() const;

    ParamSpec m_spec;
    double m_value = 0;
    QString m_shown;  // the text of m_value, to tell an edit from a field left as it was
    QString m_problem;
};

}  // namespace lenslab::gui
