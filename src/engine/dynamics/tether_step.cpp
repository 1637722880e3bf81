// The exact spring-damper step in float, the control laws' precision, compiled once here
// (tether_step.hpp has the formulas, tether_step_impl.hpp the definitions).
#include "dynamics/tether_step.hpp"

namespace feel::detail {

template MassStateF tether_step<float>(const SpringDamperF&, MassStateF, float) noexcept;
template float tether_omega<float>(const SpringDamperF&) noexcept;
template int32_t tether_substeps<float>(const SpringDamperF&, float, int32_t) noexcept;
template bool tether_crossing<float>(const SpringDamperF&, MassStateF, float, float, float&) noexcept;
template bool tether_crossing<float>(const SpringDamperF&, MassStateF, MassStateF, float, float, float&,
                                     MassStateF&) noexcept;

}  // namespace feel::detail
