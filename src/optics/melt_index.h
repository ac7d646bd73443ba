#pragma once
// A melt of a catalogue glass: its index moved by Δn_d and its Abbe number by ΔV_d, as a
// melt sheet gives them or a tolerance allows. The glass's dispersion keeps its shape,
// scaled about n_d: n'(λ) = n_d + Δn_d + s (n(λ) - n_d), with s chosen so that
// (n'_d - 1) / (n'_F - n'_C) is exactly V_d + ΔV_d.

#include "optics/glass.h"

namespace lenslab {

IndexModelPtr melt_index(IndexModelPtr glass, double delta_n_d, double delta_v_d);

}  // namespace lenslab
