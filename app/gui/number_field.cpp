#include "number_field.h"

#include <QFontMetrics>
#include <QKeyEvent>
#include <QWheelEvent>
#include <algorithm>
#include <charconv>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

namespace lenslab::gui {

namespace {

// The ways a declared unit may be written after a number.
std::vector<std::string> spellings_of(const std::string& unit) {
    if (unit == "degrees") return {"degrees", "degree", "deg", "°"};
    if (unit == "seconds") return {"seconds", "second", "sec", "s"};
    if (unit == "mm") return {"mm", "millimetres", "millimeters"};
    if (unit == "nm") return {"nm", "nanometres", "nanometers"};
    return {unit};
}

}  // namespace

ParsedNumber parse_number(const QString& text, const ParamSpec& p) {
    const std::string s = text.trimmed().toStdString();
    if (s.empty()) return {std::nullopt, QObject::tr("type a number")};
    // from_chars reads the C locale's form only ("1.5", "-12e-1"), never a grouping comma; a
    // leading plus is allowed as people write it.
    const char* begin = s.data() + (s[0] == '+' ? 1 : 0);
    const char* end = s.data() + s.size();
    double v = 0;
    const auto [rest, error] = std::from_chars(begin, end, v);
    if (error != std::errc() || !std::isfinite(v))
        return {std::nullopt, QObject::tr("not a number: '%1'").arg(text.trimmed())};
    const std::string after =
        QString::fromStdString(std::string(rest, end)).trimmed().toStdString();
    if (!after.empty()) {
        if (p.unit.empty()) {
            return {std::nullopt,
                    QObject::tr("'%1' after the number: this field takes a plain number")
                        .arg(QString::fromStdString(after))};
        }
        const auto spellings = spellings_of(p.unit);
        if (std::find(spellings.begin(), spellings.end(), after) == spellings.end()) {
            return {std::nullopt,
                    QObject::tr("'%1' is not a unit of this field (it is in %2)")
                        .arg(QString::fromStdString(after), QString::fromStdString(p.unit))};
        }
    }
    if (p.is_integer() && v != std::floor(v))
        return {std::nullopt, QObject::tr("must be a whole number, got %1").arg(format_shown(v))};
    if (const auto why = range_problem(p, v)) return {std::nullopt, QString::fromStdString(*why)};
    return {v, {}};
}

QString format_shown(double v) {
    if (v == 0) return "0";  // not "-0"
    return QString::number(v, 'g', 6);
}

NumberField::NumberField(const ParamSpec& p, QWidget* parent) : QLineEdit(parent), m_spec(p) {
    setObjectName(QString::fromStdString("field:" + p.key));
    // Wide enough for a six-digit negative number, so three abreast are never cut off.
    setMinimumWidth(fontMetrics().horizontalAdvance("-0.000000") + 12);
    setSizePolicy(QSizePolicy::Expanding, QSizePolicy::Fixed);
    setFocusPolicy(Qt::StrongFocus);
    setToolTip(documentation());
    connect(this, &QLineEdit::editingFinished, this, &NumberField::finish_editing);
    // Typing again clears the red until the text is judged on leaving the field.
    connect(this, &QLineEdit::textEdited, this, [this] {
        if (!m_problem.isEmpty()) {
            m_problem.clear();
            setStyleSheet({});
            setToolTip(documentation());
        }
    });
}

void NumberField::setValue(double v) {
    const bool had_problem = !m_problem.isEmpty();
    m_value = v;
    m_shown = format_shown(v);
    m_problem.clear();
    setStyleSheet({});
    setToolTip(documentation());
    setText(m_shown);
    if (had_problem) emit problem_cleared();
}

double NumberField::minimum() const {
    if (m_spec.kind == ParamKind::Fraction && !m_spec.min) return 0.0;
    return m_spec.min ? m_spec.min->value : -std::numeric_limits<double>::infinity();
}

double NumberField::maximum() const {
    if (m_spec.kind == ParamKind::Fraction) return 1.0;
    return m_spec.max ? m_spec.max->value : std::numeric_limits<double>::infinity();
}

QString NumberField::documentation() const {
    QString tip = QString::fromStdString(m_spec.doc);
    // range_text needs both ends of a whole number; the docs' backticks are not for tooltips.
    const bool ranged =
        m_spec.kind == ParamKind::WholeNumber
            ? m_spec.min && m_spec.max
            : m_spec.kind == ParamKind::Number || m_spec.kind == ParamKind::Fraction;
    QString range = ranged ? QString::fromStdString(range_text(m_spec)) : QString();
    range.remove('`');
    if (!range.isEmpty()) {
        if (!tip.isEmpty()) tip += "\n";
        tip += tr("Range: %1").arg(range);
    }
    if (!m_spec.unit.empty()) {
        if (!tip.isEmpty()) tip += "\n";
        tip += tr("Unit: %1").arg(QString::fromStdString(m_spec.unit));
    }
    return tip;
}

void NumberField::show_problem(const QString& reason) {
    m_problem = reason;
    setStyleSheet("QLineEdit { background: #f8d7da; color: #7b1e1e; }");
    setToolTip(reason + "\n\n" + documentation());
    emit refused(reason);
}

void NumberField::finish_editing() {
    // A field left as it was shown commits nothing (its exact value may have more digits).
    if (text().trimmed() == m_shown) {
        if (!m_problem.isEmpty()) setValue(m_value);
        return;
    }
    const ParsedNumber parsed = parse_number(text(), m_spec);
    if (!parsed.value) {
        show_problem(parsed.problem);
        return;
    }
    setValue(*parsed.value);
    emit committed(m_value);
}

void NumberField::keyPressEvent(QKeyEvent* event) {
    if (event->key() == Qt::Key_Escape && (text() != m_shown || !m_problem.isEmpty())) {
        setValue(m_value);
        event->accept();
        return;
    }
    QLineEdit::keyPressEvent(event);
}

void NumberField::wheelEvent(QWheelEvent* event) {
    // An unfocused field lets the wheel scroll the panel it sits in.
    if (!hasFocus()) {
        event->ignore();
        return;
    }
    const int notches = event->angleDelta().y() / 120;
    if (notches == 0) {
        event->ignore();
        return;
    }
    event->accept();
    // One unit in the value's second significant digit (1.0 -> 1.1, 0.06 -> 0.061).
    const double magnitude = std::abs(m_value);
    double step = magnitude > 0 ? std::pow(10.0, std::floor(std::log10(magnitude)) - 1) : 0.1;
    if (m_spec.is_integer()) step = std::max(1.0, std::round(step));
    double next = m_value + notches * step;
    next = std::round(next / step) * step;  // no drift from repeated sums
    if (m_spec.is_integer()) next = std::round(next);
    if (parse_number(format_shown(next), m_spec).value) {
        setValue(parse_number(format_shown(next), m_spec).value.value());
        emit committed(m_value);
    }
}

}  // namespace lenslab::gui
