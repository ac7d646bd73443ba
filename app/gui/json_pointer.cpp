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
    std::string out(token);
    // "~1" first: unescaping "~0" first would turn "~01" (the text "~1") into "~1" and
    // then into '/'.
    for (size_t i = out.find("~1"); i != std::string::npos; i = out.find("~1", i + 1)) {
        out.replace(i, 2, "/");
    }
    for (size_t i = out.find("~0"); i != std::string::npos; i = out.find("~0", i + 1)) {
        out.replace(i, 2, "~");
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
