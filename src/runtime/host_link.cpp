// The host's end of the queues: numbering, and force-profile samples sent ahead in chunks.
#include "feel/runtime/host_link.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace feel::runtime {

std::optional<uint32_t> HostLink::send_numbered(Command command) noexcept {
    command.sequence = next_sequence_;
    if (!commands_->try_push(command)) return std::nullopt;
    return next_sequence_++;
}

std::optional<uint32_t> HostLink::send_with_samples(Command command, std::span<const int16_t> samples) {
    const std::size_t needed = samples.empty() ? 1 : commands_for(samples.size());
    if (needed > commands_->capacity()) {
        throw std::invalid_argument("host link: " + std::to_string(samples.size()) + " samples need " +
                                    std::to_string(needed) + " commands, and the command queue holds " +
                                    std::to_string(commands_->capacity()));
    }
    // This thread is the only producer: the room seen now can only grow before the pushes.
    if (commands_->capacity() - commands_->size_approx() < needed) return std::nullopt;
    for (std::size_t offset = 0; offset < samples.size(); offset += kSamplesPerCommand) {
        const std::size_t count = std::min<std::size_t>(kSamplesPerCommand, samples.size() - offset);
        scratch_ = Command{};
        scratch_.kind = CommandKind::stage_samples;
        scratch_.sample_offset = static_cast<int32_t>(offset);
        scratch_.sample_count = static_cast<int32_t>(count);
        std::copy_n(samples.begin() + static_cast<std::ptrdiff_t>(offset), count, scratch_.samples);
        (void)send_numbered(scratch_);
    }
    return send_numbered(command);
}

std::optional<uint32_t> HostLink::keep_alive() noexcept { return send_numbered(make_keep_alive(0)); }

std::optional<uint32_t> HostLink::create(const EffectParams& params, std::span<const int16_t> samples) {
    return send_with_samples(make_create(0, params), samples);
}

std::optional<uint32_t> HostLink::update(EffectId effect, const EffectParams& params, uint32_t field_mask,
                                         bool restart, std::span<const int16_t> samples) {
    return send_with_samples(make_update(0, effect, params, field_mask, restart), samples);
}

std::optional<uint32_t> HostLink::start_effect(EffectId effect, int32_t iterations, bool solo) noexcept {
    return send_numbered(make_start(0, effect, iterations, solo));
}

std::optional<uint32_t> HostLink::stop_effect(EffectId effect) noexcept {
    return send_numbered(make_effect_command(CommandKind::stop, 0, effect));
}

std::optional<uint32_t> HostLink::destroy(EffectId effect) noexcept {
    return send_numbered(make_effect_command(CommandKind::destroy, 0, effect));
}

std::optional<uint32_t> HostLink::status(EffectId effect) noexcept {
    return send_numbered(make_effect_command(CommandKind::status, 0, effect));
}

std::optional<uint32_t> HostLink::set_gain(int32_t gain) noexcept {
    return send_numbered(make_value_command(CommandKind::set_gain, 0, gain));
}

std::optional<uint32_t> HostLink::control(DeviceControl control) noexcept {
    return send_numbered(make_device_control(0, control));
}

std::optional<uint32_t> HostLink::query_pool() noexcept { return send_numbered(make_query_pool(0)); }

std::optional<uint32_t> HostLink::assign_reflex(EffectId effect) noexcept {
    return send_numbered(make_effect_command(CommandKind::assign_reflex, 0, effect));
}

std::optional<uint32_t> HostLink::remove_reflex(EffectId effect) noexcept {
    return send_numbered(make_effect_command(CommandKind::remove_reflex, 0, effect));
}

std::optional<uint32_t> HostLink::set_idf(IdfSettings settings) noexcept {
    return send_numbered(make_set_idf(0, settings));
}

std::optional<uint32_t> HostLink::configure_safety(const SafetyConfig& config) noexcept {
    return send_numbered(make_configure_safety(0, config));
}

std::optional<uint32_t> HostLink::set_report_rate(int32_t hz) noexcept {
    return send_numbered(make_value_command(CommandKind::set_report_rate, 0, hz));
}

std::optional<uint32_t> HostLink::stream_force(std::span<const int16_t> force) noexcept {
    return send_numbered(make_stream_force(0, force));
}

}  // namespace feel::runtime
