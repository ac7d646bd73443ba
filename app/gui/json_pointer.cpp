#include "json_pointer.h"

namespace lenslab::gui {

std::string escape_pointer_token(std::string_view token) {
    std::string out;
    out.reserve(token.size());
    for (const char c : token) {
        if (c == '~') {
            out += "~0";
        } else if (c == '/') {
            out += "~1";
        } else {
            out += c;
        }
    }
    return out;
}

std::string unescape_pointer_token(std::string_view token) {
    // One pass, each "~0" or "~1" decoded once: the same as RFC 6901's "~1" then "~0", so
    // "~01" (the text "~1") never becomes '/'.
    std::string out;
    out.reserve(token.size());
    for (size_t i = 0; i < token.size(); ++i) {
        if (token[i] == '~' && i + 1 < token.size() &&
            (token[i + 1] == '0' || token[i + 1] == '1')) {
            out += token[++i] == '0' ? '~' : '/';
        } else {
            out += token[i];
        }
    }
    return out;
}

QString join_pointer(const QString& base, const QString& token) {
    return base + "/" + QString::fromStdString(escape_pointer_token(token.toStdString()));
}

QString join_pointer(const QString& base, qsizetype index) {
    return base + "/" + QString::number(index);
}

std::string append_pointer(const std::string& base, const std::string& relative) {
    return relative.empty() ? base : base + "/" + relative;
}

QStringList split_pointer(const QString& pointer) {
    QStringList tokens;
    if (pointer.isEmpty()) return tokens;
    // A pointer starts with '/', so the first part is the empty text before it.
    const QStringList parts = pointer.split('/');
    for (qsizetype i = 1; i < parts.size(); ++i) {
        tokens << QString::fromStdString(unescape_pointer_token(parts[i].toStdString()));
    }
    return tokens;
}

}  // namespace lenslab::gui
