#pragma once
// The error of a file that cannot be written: its message names the path and the reason
// ("cannot write 'out.png': no space left on device"), and lenslab exits 1.

#include "util/error.h"

namespace lenslab {

class FileWriteError : public Error {
public:
    using Error::Error;
};

}  // namespace lenslab
