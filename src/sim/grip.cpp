// Grip names, as the CLI's --grip flag spells them.
#include "feel/sim/hand.hpp"

namespace feel::sim {
namespace {

struct GripName {
    Grip grip;
    std::string_view name;
};

constexpr GripName kGripNames[] = {
    {Grip::none, "none"},   {Grip::loose, "loose"},         {Grip::firm, "firm"},
    {Grip::stiff, "stiff"}, {Grip::kinematic, "kinematic"},
};

}  // namespace

std::optional<Grip> grip_from_name(std::string_view name) noexcept {
    for (const GripName& g : kGripNames) {
        if (g.name == name) return g.grip;
    }
    return std::nullopt;
}

std::string_view grip_name(Grip g) noexcept {
    for (const GripName& n : kGripNames) {
        if (n.grip == g) return n.name;
    }
    return "unknown";
}

}  // namespace feel::sim
