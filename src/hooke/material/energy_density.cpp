#include <hooke/material/detail/energy_density_impl.hpp>
#include <hooke/material/energy_density.hpp>

namespace hooke::material {

double energy_density(Law law, const Mat2& f, const Lame& l) { return detail::psi<2>(law, f, l); }
double energy_density(Law law, const Mat3& f, const Lame& l) { return detail::psi<3>(law, f, l); }
Mat2 first_piola(Law law, const Mat2& f, const Lame& l) { return detail::piola<2>(law, f, l); }
Mat3 first_piola(Law law, const Mat3& f, const Lame& l) { return detail::piola<3>(law, f, l); }
Mat4 first_piola_derivative(Law law, const Mat2& f, const Lame& l) { return detail::piola_derivative<2>(law, f, l); }
Mat9 first_piola_derivative(Law law, const Mat3& f, const Lame& l) { return detail::piola_derivative<3>(law, f, l); }

}  // namespace hooke::material
