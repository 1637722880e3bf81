// Reflexes (§1.2.c, §6.3): a press starts the effect in the same tick, a held button
// repeats it every Trigger Repeat Interval, release ends the repeats, a burst of presses
// is never missed, many reflexes are resident at once.
//
// Each test drives a 1 kHz loop in the runtime's order (issue 5: reflexes, then
// engine.tick) and records the ticks at which the effect was started, read from the
// engine's own start counter; the expected start times follow from the definitions.
#include <gtest/gtest.h>

#include <vector>

#include "feel/engine.hpp"
#include "feel/runtime/reflexes.hpp"
#include "runtime_tick.hpp"

namespace feel::runtime {
namespace {

using test_support::kTickUs;

EffectParams jolt(int32_t magnitude, int64_t duration_us) {
    EffectParams p;
    p.type = EffectType::constant;
    p.duration_us = duration_us;
    p.axis_count = 1;
    p.axes[0] = Axis::x;
    p.constant.magnitude = magnitude;
    return p;
}

Trigger button(int32_t n) { return Trigger{TriggerKind::button, n}; }
Trigger hat(int32_t n) { return Trigger{TriggerKind::hat, n}; }
uint32_t bit(int32_t n) { return 1u << (n - 1); }

// A loop of the engine and a reflex table. `controls(t_us, buttons, hats)` sets the input
// of each tick.
struct Loop {
    Engine engine{EngineConfig{}};
    ReflexTable reflexes{64};
    int64_t t_us = 0;
    TickOutput out;

    EffectId create(const EffectParams& p) {
        const CreateResult r = engine.create(p);
        EXPECT_TRUE(r.error.ok()) << r.error.message();
        return r.id;
    }

    void tick(uint32_t buttons, uint32_t hats = 0) {
        TickInput in;
        in.t_us = t_us;
        in.buttons = buttons;
        in.hats = hats;
        reflexes.on_tick(in, engine);
        engine.tick(in, out);
        t_us += kTickUs;
    }

    // Runs until end_us and returns the tick times (µs) at which `effect` was started.
    template <class Controls>
    std::vector<int64_t> run(int64_t end_us, EffectId effect, Controls controls) {
        std::vector<int64_t> starts;
        uint32_t seen = engine.status(effect).starts;
        while (t_us < end_us) {
            uint32_t buttons = 0, hats = 0;
            controls(t_us, buttons, hats);
            const int64_t now = t_us;
            tick(buttons, hats);
            const uint32_t count = engine.status(effect).starts;
            for (; seen < count; ++seen) starts.push_back(now);
        }
        return starts;
    }
};

// Button n held during [from_us, to_us).
auto hold(int32_t n, int64_t from_us, int64_t to_us) {
    return [=](int64_t t, uint32_t& buttons, uint32_t&) {
        if (t >= from_us && t < to_us) buttons |= bit(n);
    };
}

TEST(Reflexes, APressStartsTheEffectInTheSameTick) {
    Loop loop;
    const EffectId id = loop.create(jolt(7000, 5000));
    ASSERT_TRUE(loop.reflexes.assign(id, button(1), 0).ok());
    for (int n = 0; n < 10; ++n) {
        loop.tick(0);
        ASSERT_EQ(loop.out.force[0], 0.0f);
    }
    // Pressed at 10 ms for 3 ms: the jolt plays 10..14 ms, from the very tick of the press.
    for (int n = 10; n < 30; ++n) {
        loop.tick(n < 13 ? bit(1) : 0);
        ASSERT_EQ(loop.out.force[0], n < 15 ? 7000.0f : 0.0f) << "t=" << n << " ms";
    }
    EXPECT_EQ(loop.engine.status(id).starts, 1u);
    EXPECT_EQ(loop.reflexes.fired(), 1u);
}

TEST(Reflexes, AHeldButtonRepeatsAtTheIntervalAndReleaseStopsIt) {
    Loop loop;
    const EffectId id = loop.create(jolt(7000, 5000));
    ASSERT_TRUE(loop.reflexes.assign(id, button(3), 25'000).ok());
    // Held from 10 ms to 110 ms: starts at 10, 35, 60, 85 ms; released at 110, none after.
    const std::vector<int64_t> starts = loop.run(300'000, id, hold(3, 10'000, 110'000));
    EXPECT_EQ(starts, (std::vector<int64_t>{10'000, 35'000, 60'000, 85'000}));
}

TEST(Reflexes, AnIntervalBetweenTicksRepeatsAtTheFirstTickAfterEachDueTime) {
    Loop loop;
    const EffectId id = loop.create(jolt(7000, 1000));
    ASSERT_TRUE(loop.reflexes.assign(id, button(1), 2500).ok());
    const std::vector<int64_t> starts = loop.run(40'000, id, hold(1, 10'000, 30'000));
    // Due at 10 + 2.5 k ms; each fires at the first 1 ms tick at or after it, no drift.
    std::vector<int64_t> expected;
    for (int k = 0; 10'000 + 2500 * k < 30'000; ++k) {
        const int64_t due = 10'000 + 2500 * k;
        expected.push_back((due + kTickUs - 1) / kTickUs * kTickUs);
    }
    EXPECT_EQ(starts, expected);
}

TEST(Reflexes, ReleaseEndsTheRepeatsButNotTheEffect) {
    Loop loop;
    const EffectId id = loop.create(jolt(4000, 50'000));  // a long rumble
    ASSERT_TRUE(loop.reflexes.assign(id, button(2), 10'000).ok());
    const std::vector<int64_t> starts = loop.run(12'000, id, hold(2, 5000, 7000));  // a 2 ms tap
    EXPECT_EQ(starts, (std::vector<int64_t>{5000}));
    EXPECT_EQ(loop.out.force[0], 4000.0f);  // at 11 ms it still plays
    EXPECT_EQ(loop.engine.state(id), EffectState::playing);
}

TEST(Reflexes, ABurstOfPressesIsNeverMissed) {
    // 30 presses at 25 Hz, each held 10 ms: faster than a host could relay them one by
    // one, yet each press edge seen at the 1 kHz tick starts the effect exactly once.
    Loop loop;
    const EffectId id = loop.create(jolt(7000, 30'000));
    ASSERT_TRUE(loop.reflexes.assign(id, button(1), 0).ok());
    auto burst = [](int64_t period_us, int64_t held_us, int presses) {
        return [=](int64_t t, uint32_t& buttons, uint32_t&) {
            const int64_t from = 10'000;
            if (t >= from && t < from + period_us * presses && (t - from) % period_us < held_us) buttons |= bit(1);
        };
    };
    std::vector<int64_t> starts = loop.run(1'500'000, id, burst(40'000, 10'000, 30));
    ASSERT_EQ(starts.size(), 30u);
    for (int k = 0; k < 30; ++k) EXPECT_EQ(starts[static_cast<size_t>(k)], 10'000 + 40'000 * k) << k;

    // A harder one: 100 presses of 2 ms every 4 ms (250 presses a second).
    Loop fast;
    const EffectId f = fast.create(jolt(7000, 3000));
    ASSERT_TRUE(fast.reflexes.assign(f, button(1), 0).ok());
    starts = fast.run(500'000, f, burst(4000, 2000, 100));
    EXPECT_EQ(starts.size(), 100u);
    EXPECT_EQ(fast.reflexes.fired(), 100u);
}

TEST(Reflexes, ManyReflexesAreResidentAtOnce) {
    Loop loop;
    std::vector<EffectId> on_button, on_hat;
    for (int32_t b = 1; b <= 32; ++b) {
        on_button.push_back(loop.create(jolt(100, 5000)));
        ASSERT_TRUE(loop.reflexes.assign(on_button.back(), button(b), 0).ok()) << b;
    }
    for (int32_t h = 1; h <= 4; ++h) {
        on_hat.push_back(loop.create(jolt(100, 5000)));
        ASSERT_TRUE(loop.reflexes.assign(on_hat.back(), hat(h), 0).ok()) << h;
    }
    EXPECT_EQ(loop.reflexes.size(), 36);
    loop.tick(0);
    // One control at a time: only its own effect starts.
    for (int32_t b = 1; b <= 32; ++b) {
        loop.tick(bit(b));
        loop.tick(0);
        for (int32_t other = 1; other <= 32; ++other) {
            ASSERT_EQ(loop.engine.status(on_button[static_cast<size_t>(other - 1)]).starts, other <= b ? 1u : 0u)
                << "button " << b << " pressed, effect of button " << other;
        }
    }
    for (int32_t h = 1; h <= 4; ++h) {
        loop.tick(0, bit(h));
        loop.tick(0);
        for (int32_t other = 1; other <= 4; ++other) {
            ASSERT_EQ(loop.engine.status(on_hat[static_cast<size_t>(other - 1)]).starts, other <= h ? 1u : 0u);
        }
    }
    // Everything at once: all 36 start in one tick and their forces add up.
    loop.tick(0xFFFF'FFFFu, 0xFu);
    EXPECT_EQ(loop.out.playing_effects, 36);
    EXPECT_EQ(loop.out.force[0], 3600.0f);
}

TEST(Reflexes, AHatAndTheButtonOfTheSameNumberAreDifferentControls) {
    Loop loop;
    const EffectId id = loop.create(jolt(7000, 5000));
    ASSERT_TRUE(loop.reflexes.assign(id, hat(2), 0).ok());
    loop.tick(0);
    loop.tick(bit(2), 0);  // button 2
    EXPECT_EQ(loop.engine.status(id).starts, 0u);
    loop.tick(0, bit(2));  // hat 2
    EXPECT_EQ(loop.engine.status(id).starts, 1u);
}

TEST(Reflexes, AButtonAlreadyHeldIsNotAPress) {
    Loop loop;
    const EffectId id = loop.create(jolt(7000, 5000));
    ASSERT_TRUE(loop.reflexes.assign(id, button(1), 10'000).ok());
    // Held from the first tick the table sees: no press, no repeats.
    std::vector<int64_t> starts = loop.run(50'000, id, hold(1, 0, 50'000));
    EXPECT_TRUE(starts.empty());
    // Held when a reflex is assigned: the same.
    const EffectId other = loop.create(jolt(7000, 5000));
    ASSERT_TRUE(loop.reflexes.assign(other, button(1), 10'000).ok());
    starts = loop.run(80'000, other, hold(1, 0, 70'000));
    EXPECT_TRUE(starts.empty());
    // The next real press fires both.
    starts = loop.run(90'000, other, hold(1, 85'000, 86'000));
    EXPECT_EQ(starts, (std::vector<int64_t>{85'000}));
    EXPECT_EQ(loop.engine.status(id).starts, 1u);
}

TEST(Reflexes, PauseIgnoresPressesAndFreezesTheRepeatSchedule) {
    Loop loop;
    const EffectId id = loop.create(jolt(7000, 2000));
    ASSERT_TRUE(loop.reflexes.assign(id, button(1), 20'000).ok());
    // Pressed at 10 ms and held; repeats due at 30 ms. Paused from 20 to 60 ms (40 ms), so
    // the repeat comes at 70 ms, then 90 ms.
    auto controls = [&](int64_t t, uint32_t& buttons, uint32_t&) {
        if (t == 20'000) loop.engine.pause();
        if (t == 60'000) loop.engine.resume();
        if (t >= 10'000 && t < 100'000) buttons |= bit(1);
    };
    std::vector<int64_t> starts = loop.run(120'000, id, controls);
    EXPECT_EQ(starts, (std::vector<int64_t>{10'000, 70'000, 90'000}));

    // A press made while paused is dropped: nothing starts on resume.
    auto paused_press = [&](int64_t t, uint32_t& buttons, uint32_t&) {
        if (t == 130'000) loop.engine.pause();
        if (t == 150'000) loop.engine.resume();
        if (t >= 135'000 && t < 140'000) buttons |= bit(1);
    };
    starts = loop.run(200'000, id, paused_press);
    EXPECT_TRUE(starts.empty());
}

TEST(Reflexes, ARestartUsesTheEffectsOwnIterations) {
    Loop loop;
    EffectParams p = jolt(7000, 3000);
    p.iterations = 2;
    const EffectId id = loop.create(p);
    ASSERT_TRUE(loop.reflexes.assign(id, button(1), 0).ok());
    loop.tick(0);
    loop.tick(bit(1));  // 1 ms: plays 2 x 3 ms
    for (int n = 0; n < 5; ++n) loop.tick(0);
    EXPECT_EQ(loop.out.force[0], 7000.0f);  // 6 ms: the last tick of the second iteration
    loop.tick(0);
    EXPECT_EQ(loop.out.force[0], 0.0f);
    EXPECT_EQ(loop.engine.status(id).completed_iterations, 2);
}

TEST(Reflexes, AReflexOfAFreedEffectRemovesItself) {
    Loop loop;
    const EffectId id = loop.create(jolt(7000, 5000));
    ASSERT_TRUE(loop.reflexes.assign(id, button(1), 0).ok());
    ASSERT_TRUE(loop.engine.destroy(id).ok());
    const EffectId successor = loop.create(jolt(1000, 5000));  // reuses the slot
    ASSERT_EQ(successor.index, id.index);
    loop.tick(0);
    loop.tick(bit(1));
    EXPECT_EQ(loop.engine.status(successor).starts, 0u);  // the stale reflex did not reach it
    EXPECT_EQ(loop.reflexes.size(), 0);
    EXPECT_EQ(loop.reflexes.dropped_stale(), 1u);
    EXPECT_EQ(loop.reflexes.fired(), 0u);
}

TEST(Reflexes, AssignReplacesRemoveAndClearForget) {
    Loop loop;
    const EffectId id = loop.create(jolt(7000, 5000));
    ASSERT_TRUE(loop.reflexes.assign(id, button(1), 0).ok());
    ASSERT_TRUE(loop.reflexes.assign(id, button(5), 1000).ok());  // replaces
    EXPECT_EQ(loop.reflexes.size(), 1);
    ASSERT_NE(loop.reflexes.find(id), nullptr);
    EXPECT_EQ(loop.reflexes.find(id)->trigger, button(5));
    EXPECT_EQ(loop.reflexes.find(id)->repeat_interval_us, 1000);
    loop.tick(0);
    loop.tick(bit(1));
    EXPECT_EQ(loop.engine.status(id).starts, 0u);
    ASSERT_TRUE(loop.reflexes.remove(id).ok());
    EXPECT_EQ(loop.reflexes.remove(id).code, ErrorCode::invalid_handle);
    loop.tick(bit(5));
    EXPECT_EQ(loop.engine.status(id).starts, 0u);
    ASSERT_TRUE(loop.reflexes.assign(id, button(5), 0).ok());
    loop.reflexes.clear();
    EXPECT_EQ(loop.reflexes.size(), 0);
    EXPECT_EQ(loop.reflexes.find(id), nullptr);
}

TEST(Reflexes, BadAssignmentsAreRefusedWithTheRangeAndChangeNothing) {
    ReflexTable table(2);
    const EffectId id{0, 0};
    struct Case {
        Trigger trigger;
        int64_t interval;
        const char* field;
        int64_t max;
    };
    const Case cases[] = {
        {Trigger{}, 0, "trigger_button", 0},
        {button(0), 0, "trigger_button", 32},
        {button(33), 0, "trigger_button", 32},
        {hat(5), 0, "trigger_button", 4},
        {button(1), -1, "trigger_repeat_interval_us", 65'000'000},
        {button(1), 65'000'001, "trigger_repeat_interval_us", 65'000'000},
    };
    for (const Case& c : cases) {
        const Error e = table.assign(id, c.trigger, c.interval);
        EXPECT_EQ(e.code, ErrorCode::invalid_parameter) << c.field << " " << c.trigger.index;
        EXPECT_STREQ(e.field, c.field);
        if (c.max != 0) {
            EXPECT_TRUE(e.has_range);
            EXPECT_EQ(e.allowed.max, c.max);
        }
    }
    EXPECT_EQ(table.assign(EffectId{}, button(1), 0).code, ErrorCode::invalid_handle);
    EXPECT_EQ(table.size(), 0);
    ASSERT_TRUE(table.assign(EffectId{0, 0}, button(1), 0).ok());
    ASSERT_TRUE(table.assign(EffectId{1, 0}, button(2), 0).ok());
    EXPECT_EQ(table.assign(EffectId{2, 0}, button(3), 0).code, ErrorCode::device_full);
    EXPECT_EQ(table.size(), 2);
    EXPECT_EQ(table.find(EffectId{2, 0}), nullptr);
}

TEST(Reflexes, ABadCapacityMakesATableThatRefusesEverything) {
    for (int32_t bad : {0, -3, 65536}) {
        ReflexTable table(bad);
        EXPECT_EQ(table.config_error().code, ErrorCode::invalid_parameter) << bad;
        EXPECT_STREQ(table.config_error().field, "capacity");
        EXPECT_EQ(table.capacity(), 0);
        EXPECT_EQ(table.assign(EffectId{0, 0}, button(1), 0).code, ErrorCode::invalid_parameter);
    }
}

// The Trigger Button and Trigger Repeat Interval of the Effect Structure (§6.3), as a
// sensation file sets them, become reflexes.
TEST(Reflexes, EffectsWithATriggerBecomeReflexes) {
    Loop loop;
    EffectParams gun = jolt(7000, 5000);
    gun.trigger = button(1);
    gun.trigger_repeat_interval_us = 100'000;
    EffectParams missile = jolt(7500, 30'000);
    missile.trigger = hat(2);
    const EffectParams plain = jolt(1000, kInfiniteUs);
    const std::vector<EffectId> ids = {loop.create(gun), loop.create(missile), loop.create(plain)};
    ASSERT_TRUE(loop.reflexes.assign_all(loop.engine, ids).ok());
    EXPECT_EQ(loop.reflexes.size(), 2);
    ASSERT_NE(loop.reflexes.find(ids[0]), nullptr);
    EXPECT_EQ(loop.reflexes.find(ids[0])->trigger, button(1));
    EXPECT_EQ(loop.reflexes.find(ids[0])->repeat_interval_us, 100'000);
    ASSERT_NE(loop.reflexes.find(ids[1]), nullptr);
    EXPECT_EQ(loop.reflexes.find(ids[1])->trigger, hat(2));
    EXPECT_EQ(loop.reflexes.find(ids[2]), nullptr);
    loop.tick(0);
    loop.tick(0, bit(2));
    EXPECT_EQ(loop.out.force[0], 7500.0f);

    // An update that clears the trigger, re-read with assign_from, removes the reflex.
    EffectParams untriggered = missile;
    untriggered.trigger = Trigger{};
    ASSERT_TRUE(loop.engine.update(ids[1], untriggered, effect_field::kTrigger, false).ok());
    ASSERT_TRUE(loop.reflexes.assign_from(loop.engine, ids[1]).ok());
    EXPECT_EQ(loop.reflexes.find(ids[1]), nullptr);
}

TEST(Reflexes, AssignAllIsAllOrNothing) {
    Engine engine{EngineConfig{}};
    ReflexTable table(2);
    EffectParams triggered = jolt(1000, 5000);
    std::vector<EffectId> ids;
    for (int32_t b = 1; b <= 3; ++b) {
        triggered.trigger = button(b);
        ids.push_back(engine.create(triggered).id);
    }
    EXPECT_EQ(table.assign_all(engine, ids).code, ErrorCode::device_full);  // 3 into 2
    EXPECT_EQ(table.size(), 0);
    const std::vector<EffectId> with_stale = {ids[0], EffectId{40, 0}};
    EXPECT_EQ(table.assign_all(engine, with_stale).code, ErrorCode::invalid_handle);
    EXPECT_EQ(table.size(), 0);
    const std::vector<EffectId> twice = {ids[0], ids[1], ids[0]};  // a repeat takes no room
    EXPECT_TRUE(table.assign_all(engine, twice).ok());
    EXPECT_EQ(table.size(), 2);
}

}  // namespace
}  // namespace feel::runtime
