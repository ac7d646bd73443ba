#pragma once
// An error in a scene or its JSON, named by its JSON path. Kept apart from the reader so
// that analysis and the apps can throw and catch it without the reader's machinery.

#include <string>

#include "util/error.h"

namespace lenslab {

// what() is "path: reason".
class SceneError : public Error {
public:
    SceneError(const std::string& path, const std::string& reason)
        : Error(path.empty() ? reason : path + ": " + reason), m_path(path), m_reason(reason) {}
    const std::string& path() const { return m_path; }
    const std::string& reason() const { return m_reason; }

private:
    std::string m_path;
    std::string m_reason;
};

}  // namespace lenslab
