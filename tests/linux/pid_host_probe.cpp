// pid_host_probe: the host API over hidraw (feel::host::PidDevice) plays every PID effect
// type on feel's USB gadget in the VM (tests/linux/init.sh), through the real kernel USB
// stack: Create New Effect and PID Block Load on ep0, the effect's reports, Effect
// Operation and Block Free on the interrupt OUT endpoint.
//
// It prints what it asked, one line per report the device must have received, in order:
//   pid caps feel_device=1 types=12 max_effects=32 pool_bytes=16384
//   pid expect set_feature create_new_effect type_usage=0x26
//   pid expect output_report set_constant_force block=1 magnitude=-6100
//   ...
//   pid done effects=11 errors=0
// The tokens are feel's units as the host was asked for them (the device log writes what
// it decoded in the same units), so tests/linux/check_pid_host_log.cpp can match them
// against the device's log without knowing the layout.
#include <cstdio>
#include <string>
#include <vector>

#include "feel/host/pid_device.hpp"

namespace {

using namespace feel;

struct Case {
    EffectType type;
    unsigned usage;  // PID 1.0's Effect Type usage (the specification's table)
};

constexpr Case kCases[] = {
    {EffectType::constant, 0x26}, {EffectType::ramp, 0x27},    {EffectType::square, 0x30},
    {EffectType::sine, 0x31},     {EffectType::triangle, 0x32}, {EffectType::saw_up, 0x33},
    {EffectType::saw_down, 0x34}, {EffectType::spring, 0x40},   {EffectType::damper, 0x41},
    {EffectType::inertia, 0x42},  {EffectType::friction, 0x43},
};

void expect(const std::string& line) { std::printf("pid expect %s\n", line.c_str()); }

std::string block_of(uint16_t b) { return " block=" + std::to_string(b); }

// A distinct, valid effect per type, so that no report of one can be taken for another's.
EffectParams params_for(EffectType t, int index) {
    EffectParams p;
    p.type = t;
    p.duration_us = 300'000 + 10'000 * index;
    p.gain = 9000 - 100 * index;
    p.axis_count = 1;
    p.axes[0] = Axis::x;
    if (t == EffectType::constant) p.constant.magnitude = -6100;
    if (t == EffectType::ramp) p.ramp = {-3000, 4500};
    if (is_periodic(t)) {
        p.periodic.magnitude = 5000 + 100 * index;
        p.periodic.offset = -200 * index;
        p.periodic.period_us = 20'000 + 1000 * index;
        p.periodic.phase = 4500 * (index % 4);
    }
    if (t == EffectType::spring || t == EffectType::damper || t == EffectType::inertia || t == EffectType::friction) {
        p.axis_count = 2;
        p.axes[1] = Axis::y;
        for (int a = 0; a < 2; ++a) {
            p.conditions[a].pos_coefficient = 500 * (index - 6) + 100 * a;
            p.conditions[a].neg_coefficient = 500 * (index - 6) + 100 * a;
            p.conditions[a].offset = 50 * a - 25 * index;
            p.conditions[a].pos_saturation = 8000;
            p.conditions[a].neg_saturation = 8000;
            p.conditions[a].deadband = 10 * index;
        }
    }
    return p;
}

}  // namespace

int main(int argc, char** argv) {
    const std::string node = argc > 1 ? argv[1] : "/dev/hidraw0";
    feel::host::Result<feel::host::PidDevice> device = feel::host::PidDevice::open("hidraw:" + node);
    if (!device) {
        std::printf("pid error open: %s\n", device.status().message.c_str());
        return 1;
    }
    const feel::host::PidCaps& caps = device->capabilities();
    int types = 0;
    for (const auto& e : caps.effect_types) types += e.usable ? 1 : 0;
    std::printf("pid caps feel_device=%d types=%d max_effects=%d pool_bytes=%d\n", caps.feel_device ? 1 : 0, types,
                caps.max_effects, caps.pool_bytes);
    int errors = 0;
    int played = 0;
    int index = 0;
    for (const Case& c : kCases) {
        const EffectParams p = params_for(c.type, index++);
        feel::host::Result<uint16_t> block = device->create_effect(p);
        char usage[16];
        std::snprintf(usage, sizeof usage, "0x%02X", c.usage);
        expect("set_feature create_new_effect type_usage=" + std::string(usage));
        if (!block) {
            std::printf("pid error create %s: %s\n", std::string(effect_type_name(c.type)).c_str(),
                        block.status().message.c_str());
            ++errors;
            continue;
        }
        const uint16_t b = *block;
        if (c.type == EffectType::constant) {
            expect("output_report set_constant_force" + block_of(b) + " magnitude=" + std::to_string(p.constant.magnitude));
        } else if (c.type == EffectType::ramp) {
            expect("output_report set_ramp_force" + block_of(b) + " start=" + std::to_string(p.ramp.start) +
                   " end=" + std::to_string(p.ramp.end));
        } else if (is_periodic(c.type)) {
            expect("output_report set_periodic" + block_of(b) + " magnitude=" + std::to_string(p.periodic.magnitude) +
                   " offset=" + std::to_string(p.periodic.offset) + " phase=" + std::to_string(p.periodic.phase) +
                   " period_ms=" + std::to_string(p.periodic.period_us / 1000));
        } else {
            for (int a = 0; a < p.axis_count; ++a) {
                const ConditionBlock& k = p.conditions[a];
                expect("output_report set_condition" + block_of(b) + " axis_index=" + std::to_string(a) +
                       " center_offset=" + std::to_string(k.offset) + " pos_coefficient=" + std::to_string(k.pos_coefficient) +
                       " neg_coefficient=" + std::to_string(k.neg_coefficient) + " pos_saturation=" +
                       std::to_string(k.pos_saturation) + " neg_saturation=" + std::to_string(k.neg_saturation) +
                       " deadband=" + std::to_string(k.deadband));
            }
        }
        expect("output_report set_effect" + block_of(b) + " type_usage=" + usage + " duration_ms=" +
               std::to_string(p.duration_us / 1000) + " gain=" + std::to_string(p.gain));
        if (!device->start(b, 2).ok()) ++errors;
        expect("output_report effect_operation" + block_of(b) + " operation_usage=0x79 loop_count=2");
        if (!device->stop(b).ok()) ++errors;
        expect("output_report effect_operation" + block_of(b) + " operation_usage=0x7B");
        if (!device->free_effect(b).ok()) ++errors;
        expect("output_report block_free" + block_of(b));
        ++played;
    }
    device->close();
    std::printf("pid done effects=%d errors=%d\n", played, errors);
    return errors == 0 ? 0 : 1;
}
