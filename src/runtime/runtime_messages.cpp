// Names of the runtime's message kinds, for logs and test messages.
#include "feel/runtime/runtime_messages.hpp"

namespace feel::runtime {

const char* command_kind_name(CommandKind kind) noexcept {
    switch (kind) {
        case CommandKind::keep_alive: return "keep_alive";
        case CommandKind::release_host: return "release_host";
        case CommandKind::create: return "create";
        case CommandKind::update: return "update";
        case CommandKind::start: return "start";
        case CommandKind::stop: return "stop";
        case CommandKind::destroy: return "destroy";
        case CommandKind::status: return "status";
        case CommandKind::set_gain: return "set_gain";
        case CommandKind::device_control: return "device_control";
        case CommandKind::query_pool: return "query_pool";
        case CommandKind::assign_reflex: return "assign_reflex";
        case CommandKind::remove_reflex: return "remove_reflex";
        case CommandKind::set_idf: return "set_idf";
        case CommandKind::configure_safety: return "configure_safety";
        case CommandKind::set_report_rate: return "set_report_rate";
        case CommandKind::stage_samples: return "stage_samples";
        case CommandKind::stream_force: return "stream_force";
    }
    return "unknown command";
}

const char* device_control_name(DeviceControl control) noexcept {
    switch (control) {
        case DeviceControl::actuators_on: return "actuators_on";
        case DeviceControl::actuators_off: return "actuators_off";
        case DeviceControl::stop_all: return "stop_all";
        case DeviceControl::reset: return "reset";
        case DeviceControl::pause: return "pause";
        case DeviceControl::resume: return "resume";
    }
    return "unknown device control";
}

const char* reported_effect_state_name(ReportedEffectState state) noexcept {
    switch (state) {
        case ReportedEffectState::stopped: return "stopped";
        case ReportedEffectState::playing: return "playing";
        case ReportedEffectState::delayed: return "delayed";
        case ReportedEffectState::emulated: return "emulated";
    }
    return "unknown state";
}

}  // namespace feel::runtime
