// The engine alone against an installed feel::engine: a constant force of 3000 on x (no
// direction: the axis's own sign) at half gain must command 1500 on x (§6.3: an effect's
// gain scales its force).
#include <cstdio>

#include "feel/engine.hpp"

int main() {
    feel::Engine engine(feel::EngineConfig{});
    feel::EffectParams p;
    p.type = feel::EffectType::constant;
    p.constant.magnitude = 3000;
    p.gain = 5000;
    const feel::CreateResult created = engine.create(p);
    if (created.error || engine.start(created.id)) {
        std::fprintf(stderr, "the engine refused the constant force\n");
        return 1;
    }
    feel::TickInput in{};
    feel::TickOutput out{};
    engine.tick(in, out);
    std::printf("force x = %.0f\n", static_cast<double>(out.force[0]));
    return out.force[0] == 1500.0f ? 0 : 1;
}
