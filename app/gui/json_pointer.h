#pragma once
// JSON pointers (RFC 6901) as the editor builds and reads them. A token holding '~' or '/'
// (a material named "a~b/c") must be escaped, '~' as "~0" and '/' as "~1", or the pointer
// names something else (or nothing) and nlohmann::json refuses it. Every pointer the editor
// joins or splits goes through these.

#include <QString>
#include <QStringList>
#include <string>
#include <string_view>

namespace lenslab::gui {

// One token, escaped for a pointer: "a~b/c" -> "a~0b~1c".
std::string escape_pointer_token(std::string_view token);
// The reverse: "~1" -> '/', then "~0" -> '~' (in that order, so "~01" becomes "~1").
std::string unescape_pointer_token(std::string_view token);

// `base` + "/" + the escaped token: join_pointer("/materials", "a/b") == "/materials/a~1b".
QString join_pointer(const QString& base, const QString& token);
QString join_pointer(const QString& base, qsizetype index);
// `base` + "/" + `relative`, a pointer relative to `base` whose tokens are already escaped
// ("emission/intensity"); an empty `relative` is `base` itself.
std::string append_pointer(const std::string& base, const std::string& relative);

// The unescaped tokens of a pointer: "/materials/a~1b" -> {"materials", "a/b"}; "" -> {}.
QStringList split_pointer(const QString& pointer);

}  // namespace lenslab::gui
