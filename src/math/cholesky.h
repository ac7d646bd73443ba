#pragma once
// Dense symmetric positive definite systems: the normal equations of least-squares fits (the
// optimiser's damped steps, Zernike fits).

#include <optional>
#include <vector>

namespace lenslab {

// Solves A x = b (A n x n, row-major) by Cholesky factorisation; none when A is not positive
// definite.
std::optional<std::vector<double>> solve_cholesky(std::vector<double> a, std::vector<double> b);

}  // namespace lenslab
