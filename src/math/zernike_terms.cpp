#include "math/zernike_terms.h"

#include <cmath>
#include <cstdlib>
#include <stdexcept>

namespace lenslab {

namespace {

constexpr int kFringeTerms = 37;

double factorial(int k) {
    double f = 1;
    for (int i = 2; i <= k; ++i) f *= i;
    return f;
}

double binomial(int n, int k) { return factorial(n) / (factorial(k) * factorial(n - k)); }

// R_n^m(ρ), m ≥ 0 and n − m even.
double zernike_radial(int n, int m, double rho) {
    double sum = 0;
    for (int s = 0; s <= (n - m) / 2; ++s) {
        const double c = factorial(n - s) /
                         (factorial(s) * factorial((n + m) / 2 - s) * factorial((n - m) / 2 - s));
        sum += (s % 2 ? -c : c) * std::pow(rho, n - 2 * s);
    }
    return sum;
}

ZernikeIndex noll_index(int j) {
    int n = 0;
    while ((n + 1) * (n + 2) / 2 < j) ++n;
    const int k = j - n * (n + 1) / 2 - 1;  // place within the row of order n
    const int m = n % 2 == 0 ? 2 * ((k + 1) / 2) : 2 * (k / 2) + 1;
    return {n, m == 0 || j % 2 == 0 ? m : -m};
}

ZernikeIndex fringe_index(int j) {
    if (j == kFringeTerms) return {12, 0};  // the set ends with 5th-order spherical's successor
    // Groups of equal (n + |m|)/2 = g hold |m| = g, g−1, ..., 0, cos before sin.
    int first = 1;  // the first term of group g
    for (int g = 0;; ++g) {
        const int size = 2 * g + 1;
        if (j < first + size) {
            const int k = j - first;
            const int m = g - k / 2;
            return {2 * g - m, k % 2 == 0 ? m : -m};
        }
        first += size;
    }
}

}  // namespace

const char* zernike_ordering_name(ZernikeOrdering ordering) {
    return ordering == ZernikeOrdering::Noll ? "noll" : "fringe";
}

ZernikeIndex zernike_index(ZernikeOrdering ordering, int j) {
    if (j < 1) throw std::invalid_argument("Zernike terms count from 1");
    if (ordering == ZernikeOrdering::Fringe) {
        if (j > kFringeTerms)
            throw std::invalid_argument("the Fringe ordering has 37 terms; Noll has any number");
        return fringe_index(j);
    }
    return noll_index(j);
}

double zernike_value(ZernikeOrdering ordering, int j, double rho, double theta) {
    const ZernikeIndex z = zernike_index(ordering, j);
    const int m = std::abs(z.m);
    double value = zernike_radial(z.n, m, rho);
    if (z.m > 0) value *= std::cos(m * theta);
    if (z.m < 0) value *= std::sin(m * theta);
    if (ordering == ZernikeOrdering::Noll) value *= std::sqrt((m == 0 ? 1.0 : 2.0) * (z.n + 1));
    return value;
}

std::vector<double> zernike_monomials(ZernikeOrdering ordering, int j) {
    const ZernikeIndex z = zernike_index(ordering, j);
    const int n = z.n, m = std::abs(z.m), size = n + 1;
    std::vector<double> c(size * size, 0.0);
    const double norm =
        ordering == ZernikeOrdering::Noll ? std::sqrt((m == 0 ? 1.0 : 2.0) * (n + 1)) : 1.0;
    // (x + iy)^m: its real part (cos mθ ρ^m) takes the even powers of iy, its imaginary part
    // (sin mθ ρ^m) the odd ones; each times (x² + y²)^p for the radial polynomial's ρ^(2p).
    for (int k = 0; k <= m; ++k) {
        if ((k % 2 == 1) != (z.m < 0)) continue;
        const double sign = (k / 2) % 2 ? -1.0 : 1.0;
        const double angular = sign * binomial(m, k);  // x^(m-k) y^k
        for (int s = 0; s <= (n - m) / 2; ++s) {
            const double radial =
                (s % 2 ? -1.0 : 1.0) * factorial(n - s) /
                (factorial(s) * factorial((n + m) / 2 - s) * factorial((n - m) / 2 - s));
            const int p = (n - m) / 2 - s;  // ρ^(n - 2s) = ρ^m (x² + y²)^p
            for (int q = 0; q <= p; ++q) {
                const int a = m - k + 2 * q, b = k + 2 * (p - q);
                c[a * size + b] += norm * radial * angular * binomial(p, q);
            }
        }
    }
    return c;
}

}  // namespace lenslab
