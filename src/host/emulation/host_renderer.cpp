// HostRenderer: the engine, ticked once per host update (host_renderer.hpp).
#include "host_renderer.hpp"

#include <algorithm>

namespace feel::host::emulation {

HostRenderer::HostRenderer(const EngineConfig& config) : engine_(config), axis_count_(config.axis_count) {}

CreateResult HostRenderer::create(const EffectParams& params, std::span<const int16_t> samples) noexcept {
    return engine_.create(params, samples);
}

Error HostRenderer::destroy(EffectId id) noexcept { return engine_.destroy(id); }

Error HostRenderer::start(EffectId id, int32_t iterations, bool solo) noexcept {
    if (iterations == kOwnIterations) {
        // The effect's own count (the host API's runtime::kEffectIterations).
        EffectParams own;
        if (const Error e = engine_.params(id, own); !e.ok()) return e;
        iterations = own.iterations;
    }
    return engine_.start(id, iterations, solo);
}

Error HostRenderer::stop(EffectId id) noexcept { return engine_.stop(id); }

void HostRenderer::stop_all() noexcept { engine_.stop_all(); }

Error HostRenderer::update(EffectId id, const EffectParams& params, uint32_t field_mask, bool restart,
                           std::span<const int16_t> samples) noexcept {
    return engine_.update(id, params, field_mask, restart, samples);
}

EffectStatus HostRenderer::status(EffectId id) const noexcept { return engine_.status(id); }

void HostRenderer::pause() noexcept { engine_.pause(); }

void HostRenderer::resume() noexcept { engine_.resume(); }

const TickOutput& HostRenderer::render(int64_t t_us, std::span<const float> position, uint32_t buttons,
                                       uint32_t hats) noexcept {
    TickInput in;
    // The engine's time never runs backwards: a caller's clock that does is held.
    in.t_us = std::max(t_us, last_t_us_);
    last_t_us_ = in.t_us;
    const std::size_t n = std::min<std::size_t>(position.size(), kMaxAxes);
    for (std::size_t i = 0; i < n; ++i) in.position[i] = position[i];
    in.buttons = buttons;
    in.hats = hats;
    engine_.tick(in, last_);
    ++updates_;
    return last_;
}

}  // namespace feel::host::emulation
