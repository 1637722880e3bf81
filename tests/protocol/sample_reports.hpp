// One report of every kind with every field set away from its default (and away from 0
// where the range allows), for round trips and seed corpora. Values are chosen by hand
// inside each field's documented range (reports.hpp, effect.hpp).
#pragma once

#include <algorithm>
#include <cstring>
#include <vector>

#include "feel/protocol/reports.hpp"

namespace feel::protocol::test {

template <std::size_t N>
void set_text(char (&dst)[N], const char* text) {
    std::memset(dst, 0, N);
    std::memcpy(dst, text, std::min(std::strlen(text), N));  // NUL-padded, unterminated when full
}

inline std::vector<AnyReport> sample_reports() {
    std::vector<AnyReport> all;

    SetEffectReport effect;
    effect.sequence = 0xA1B2C3D4u;
    effect.block = 513;
    effect.type = EffectType::sweep_triangle;
    effect.duration_us = 65'000'000;
    effect.start_delay_us = 1'234'567;
    effect.trigger_repeat_interval_us = 250'000;
    effect.gain = 7321;
    effect.iterations = 255;  // finite: infinite is kLoopInfinite
    effect.trigger_kind = TriggerKind::hat;
    effect.trigger_index = 3;
    effect.axis_count = 3;
    effect.axes[0] = Axis::rz;
    effect.axes[1] = Axis::x;
    effect.axes[2] = Axis::ry;
    effect.direction_kind = DirectionKind::cartesian;
    effect.direction[0] = -10000;
    effect.direction[1] = 10000;
    effect.direction[2] = -1;
    effect.has_envelope = true;
    all.emplace_back(effect);

    SetEffectReport endless = effect;  // kWireInfinite is the one value outside 1..65e6
    endless.sequence = 0;
    endless.duration_us = kWireInfinite;
    endless.type = EffectType::dynamic_paddle;
    endless.iterations = kLoopInfinite;
    endless.direction_kind = DirectionKind::spherical;  // PID's Ordinals carry the angles
    endless.direction[0] = 35999;
    endless.direction[1] = 18000;
    endless.direction[2] = 0;  // spherical has two slots; the third does not travel
    endless.has_envelope = false;
    all.emplace_back(endless);

    all.emplace_back(SetEnvelopeReport{7, 2, 9999, 65'000'000, 1, 3});
    all.emplace_back(SetEnvelopeReport{7, 2, 9999, 999, 1, 64'999'001});  // sub-millisecond parts
    all.emplace_back(SetConditionReport{8, 65535, 5, -10000, 10000, -1, 0, 4321, 10000,
                                        OffsetMode::relative});
    all.emplace_back(SetPeriodicReport{9, 40, -7000, 2500, 35999, 65'000'000});
    all.emplace_back(SetConstantForceReport{10, 41, -10000});
    all.emplace_back(SetRampForceReport{11, 42, 10000, -9999});
    all.emplace_back(SetCustomForceReport{12, 43, 6, 65'000'000, 65535});

    CustomForceDataReport data;
    data.sequence = 13;
    data.block = 44;
    data.offset = 65534;
    data.count = kSamplesPerDataReport;
    for (int i = 0; i < kSamplesPerDataReport; ++i) data.samples[i] = static_cast<int16_t>(i * 625 - 10000);
    all.emplace_back(data);

    DownloadForceSampleReport stream;
    stream.sequence = 14;
    stream.axis_count = 6;
    const int16_t forces[kMaxAxes] = {-10000, 10000, -1, 1, 4096, -4096};
    for (int i = 0; i < kMaxAxes; ++i) stream.force[i] = forces[i];
    all.emplace_back(stream);

    all.emplace_back(EffectOperationReport{15, 45, EffectOperation::start_solo, kLoopInfinite});
    all.emplace_back(BlockFreeReport{16, 46});
    all.emplace_back(DeviceControlReport{17, DeviceControlOp::device_continue});
    all.emplace_back(DeviceGainReport{18, 0});

    all.emplace_back(SetTextureReport{19, 47, TextureBlock{10000, 1, 2500, 9999}});
    all.emplace_back(SetWallReport{20, 48, WallBlock{-10000, WallSense::negative, 10000,
                                                     OffsetMode::relative, 35999, 10000, 1, true}});
    all.emplace_back(SetBarrierReport{21, 49, BarrierBlock{10000, -10000, 10000, -5000, 18000, 1, 10000}});
    all.emplace_back(SetSweepReport{22, 50, 35999, 1, SweepSense::counterclockwise});

    SetDynamicReport dynamic;
    dynamic.sequence = 23;
    dynamic.block = 51;
    DynamicBlock& d = dynamic.dynamic;
    d.blast_direction = 35999;
    d.blast_intensity = -10000;
    d.blast_resonance = 10000;
    d.blast_decay = 10000;
    d.dynamic_mass = 2;
    d.impact_direction = 9000;
    d.impact_intensity = 10000;
    d.elasticity = 3;
    d.collision_absorption = 4;
    d.density = 5;
    d.settle = 6;
    d.viscosity = 7;
    d.inertia = 8;
    d.play = 9;
    d.stiffness = 10000;
    d.drift_resistance = 11;
    d.ball_mass = 12;
    d.string_length = 13;
    d.string_compliance = 14;
    d.ball_damping = 15;
    d.initial_velocity = -16;
    d.initial_velocity_direction = 17;
    d.paddle_compliance = 18;
    d.paddle_damping = 19;
    d.gravity = -10000;
    d.interim_reporting = true;
    all.emplace_back(dynamic);

    all.emplace_back(SetControlLawReport{24, 52, 5, ControlLawBlock{10000, 2, 3, 4, -10000, 10000,
                                                                    10000, 8, 9, -10}});
    all.emplace_back(ReflexReport{25, 53, false});
    all.emplace_back(IdfSettingsReport{26, runtime::IdfSettings{true, true}});
    all.emplace_back(ReportRateReport{27, 1000});
    all.emplace_back(KeepAliveReport{0xFFFFFFFFu});
    all.emplace_back(EffectStatusRequestReport{28, 54});

    all.emplace_back(CreateNewEffectReport{29, EffectType::force_profile, 65535});
    all.emplace_back(BlockLoadReport{55, BlockLoadStatus::full, 0xFFFFFFFEu});
    all.emplace_back(PidPoolReport{0xFFFFFFFFu, 65535, false, true, 12345, 7, 1u << 20, 99});

    DeviceInfoReport info;
    set_text(info.device, "iforce2");
    set_text(info.description, "I-FORCE 2.0 class joystick, simulated, with a description long en");
    info.device_class = 2;  // sim::DeviceClass::iforce2
    info.axis_count = 6;
    for (int i = 0; i < kMaxAxes; ++i) {
        info.axes[i].axis = static_cast<Axis>(kMaxAxes - 1 - i);
        info.axes[i].rotary = static_cast<uint8_t>(i % 2);
        info.axes[i].half_travel_micro = static_cast<uint32_t>(INT32_MAX - i);
        info.axes[i].max_force_milli = static_cast<uint32_t>(1 + i);
        info.axes[i].sensor_counts = static_cast<uint32_t>((1 << 24) - i);
    }
    info.button_count = 32;
    info.hat_count = 4;
    info.dead_man_switch = true;
    info.max_force = 9000;
    info.supported_types = (uint64_t{1} << 33) - 1 - (uint64_t{1} << 12);
    info.effect_slots = 65535;
    info.pool_bytes = 0xFFFFFFFFu;
    info.sample_memory = 65536;
    info.local_reflexes = true;
    info.interim_reports = true;
    info.loop_rate_hz = 1000;
    info.max_loop_rate_hz = 4000;
    info.interim_report_centihz = 6000;
    info.report_rate_hz = 250;
    set_text(info.firmware_version, "feel 0.1.0 sim firmware!");  // exactly 24: no NUL
    info.vendor_revision = 1;
    all.emplace_back(info);

    JoystickInputReport joy;
    const int16_t pos[kMaxAxes] = {-10000, 10000, 0, 1, -1, 5000};
    for (int i = 0; i < kMaxAxes; ++i) joy.position[i] = pos[i];
    joy.buttons = 0x80000001u | (1u << 13);
    joy.hats = 0x0A;
    all.emplace_back(joy);

    all.emplace_back(PidStateReport{true, false, true, true, false, true, 65535});

    CommandStatusReport status;
    status.sequence = 0x12345678u;
    status.command = ReportId::set_effect;
    status.block = 56;
    status.code = ErrorCode::invalid_parameter;
    status.value = INT64_MIN;
    status.allowed_min = -1;
    status.allowed_max = INT64_MAX;
    status.has_range = true;
    status.effect_state = 3;
    status.iterations = 255;
    status.completed_iterations = 254;
    status.elapsed_us = 0xFFFFFFFFu;
    status.last_end = 2;
    all.emplace_back(status);

    CommandErrorTextReport text;
    text.sequence = 0x12345678u;
    text.command = ReportId::set_effect;
    text.part = 2;
    set_text(text.text, "the rule's second half, NUL-padded");
    all.emplace_back(text);

    DeviceStatusReport device;
    device.t_us = 0x0123456789ABCDEFull;
    device.report_number = 0xFEDCBA98u;
    for (int i = 0; i < kMaxAxes; ++i) {
        device.force[i] = static_cast<int16_t>(i % 2 == 0 ? -10000 + i : 10000 - i);
        device.velocity[i] = i % 2 == 0 ? INT32_MIN + i : INT32_MAX - i;
    }
    device.fade_level = 5000;
    device.safety_flags = 0x1F;
    device.gain = 1;
    device.loop_rate_hz = 1000;
    device.overruns = 0xFFFFFFFFu;
    device.measured_rate_millihz = 999'987;
    all.emplace_back(device);

    EffectStatesReport effects;
    effects.report_number = 0xFEDCBA98u;
    effects.playing_effects = 3;
    effects.resident_effects = 65535;
    effects.dropped_reports = ~uint64_t{0};
    effects.page = 2;
    effects.pages = 255;
    effects.effect_count = kEffectsPerStatusReport;
    for (int i = 0; i < kEffectsPerStatusReport; ++i) {
        effects.effect_block[i] = static_cast<uint16_t>(65535 - i);
        effects.effect_state[i] = static_cast<uint8_t>(i % 4);
    }
    all.emplace_back(effects);

    DynamicReportReport dyn;
    dyn.block = 57;
    dyn.final_report = 1;
    dyn.t_us = ~uint64_t{0} - 1;
    dyn.axis_count = 6;
    dyn.first_axis = 4;
    for (int i = 0; i < kDynamicAxesPerReport; ++i) {
        dyn.position_centi[i] = INT32_MIN + i;
        dyn.velocity_centi[i] = INT32_MAX - i;
        dyn.handle_velocity_centi[i] = -i * 1000;
    }
    all.emplace_back(dyn);
    return all;
}

}  // namespace feel::protocol::test
