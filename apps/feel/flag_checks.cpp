// Range checks for command-line numbers (flag_checks.hpp).
#include "flag_checks.hpp"

#include <cmath>
#include <cstdio>

#include "cli.hpp"

namespace feel::cli {
namespace {

std::string with_unit(double value, const char* unit) {
    std::string s = number(value);
    if (unit != nullptr && *unit != '\0') s += std::string(" ") + unit;
    return s;
}

}  // namespace

std::string number(double v) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "%g", v);
    return buf;
}

int32_t checked_whole(const char* flag, double value, int32_t min, int32_t max, const char* unit) {
    const bool whole = std::isfinite(value) && std::floor(value) == value;
    if (!whole || value < min || value > max) {
        const std::string unit_words = unit != nullptr && *unit != '\0' ? std::string(" of ") + unit : "";
        throw UsageError(std::string(flag) + " = " + with_unit(value, unit) + " is out of range (allowed a whole number" +
                         unit_words + ", " + std::to_string(min) + ".." + std::to_string(max) + ")");
    }
    return static_cast<int32_t>(value);
}

double checked_range(const char* flag, double value, double min, double max, const char* unit, bool min_inclusive) {
    const bool above_min = min_inclusive ? value >= min : value > min;
    if (!std::isfinite(value) || !above_min || value > max) {
        const std::string u = unit != nullptr && *unit != '\0' ? std::string(" ") + unit : "";
        const std::string range = min_inclusive ? number(min) + ".." + number(max) + u
                                                : number(min) + " < value <= " + number(max) + u;
        throw UsageError(std::string(flag) + " = " + with_unit(value, unit) + " is out of range (allowed " + range +
                         ")");
    }
    return value;
}

const sim::DeviceProfile& checked_profile(const std::string& name) {
    if (const sim::DeviceProfile* p = sim::find_device_profile(name)) return *p;
    std::string names;
    for (const sim::DeviceProfile& p : sim::device_profiles()) {
        names += names.empty() ? "" : ", ";
        names += p.name;
    }
    throw UsageError("--profile \"" + name + "\" is not a known device (available: " + names + ")");
}

}  // namespace feel::cli
