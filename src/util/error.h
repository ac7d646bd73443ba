#pragma once
// The one base of every failure a user can act on (a bad scene, a file that cannot be
// written, more photons than memory holds): its message is printed as it stands and the
// program exits 1. Anything else that escapes is a bug in lenslab.

#include <stdexcept>

namespace lenslab {

class Error : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

}  // namespace lenslab
