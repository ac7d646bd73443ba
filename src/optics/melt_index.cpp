#include "optics/melt_index.h"

#include <sstream>

namespace lenslab {

namespace {

class MeltIndex final : public IndexModel {
public:
    MeltIndex(IndexModelPtr glass, double delta_n_d, double delta_v_d)
        : m_glass(std::move(glass)),
          m_n_d(m_glass->n_d()),
          m_delta_n_d(delta_n_d),
          m_delta_v_d(delta_v_d) {
        const double spread = m_glass->n(kLineF) - m_glass->n(kLineC);
        m_scale = (m_n_d + delta_n_d - 1.0) / ((m_glass->abbe_number() + delta_v_d) * spread);
        min_nm = m_glass->min_nm;
        max_nm = m_glass->max_nm;
    }
    double n(double nm) const override {
        return m_n_d + m_delta_n_d + m_scale * (m_glass->n(nm) - m_n_d);
    }
    std::string describe() const override {
        std::ostringstream s;
        s << m_glass->describe() << ", melt n_d " << std::showpos << m_delta_n_d << " V_d "
          << m_delta_v_d;
        return s.str();
    }

private:
    IndexModelPtr m_glass;
    double m_n_d, m_delta_n_d, m_delta_v_d, m_scale = 1.0;
};

}  // namespace

IndexModelPtr melt_index(IndexModelPtr glass, double delta_n_d, double delta_v_d) {
    if (delta_n_d == 0.0 && delta_v_d == 0.0) return glass;
    return std::make_shared<MeltIndex>(std::move(glass), delta_n_d, delta_v_d);
}

}  // namespace lenslab
