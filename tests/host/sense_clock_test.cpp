// SenseClock (src/host/emulation/sense_clock.hpp): the sense time of each Input report of a
// standard PID device, from the report sequence alone, on a simulated bursty link.
//
// The link. The device senses and sends a report every T = 4 ms (250 Hz, the VM gadget's
// rate) on its own clock, which runs 80 ppm slow against the host's. Each report reaches
// the host's queue 1 ms later plus up to 1 ms of jitter; the reader, woken by poll() up to
// 0.5 ms later, 1 time in 50 oversleeps by 10..110 ms (as a TCG guest's does), and then reads
// everything queued in one drain. Sometimes the device drops a report (a gadget that keeps only its
// newest state when the host did not poll). Truth: the sense times the simulation made.
//
// Assertions. After the clock has learned (the first seconds), the interval between two
// reports' sense times is the true interval to within 1% of a period; with drops (one in
// 200 reports) to within 2% (the period reads long by the drop rate), except around a
// drop: at most two intervals per drop are off, by a period (the drop's own, until the
// window of evidence shows it, and the skip). Stamping reports with their arrival, as the
// host did before, is shown far off on the same link (most intervals inside a burst are 0).
// Then the host's engine: a wall swept by a sine, rendered once at the true sense times and
// once at the reconstructed ones, gives the same force within the passivity damper's share
// of one period's velocity error; at arrival times it does not.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <random>
#include <vector>

#include "emulation/emulated_loop.hpp"
#include "emulation/emulation_config.hpp"
#include "emulation/host_renderer.hpp"
#include "emulation/sense_clock.hpp"
#include "feel/sim/device_profile.hpp"

namespace feel::host::emulation {
namespace {

constexpr int64_t kPeriodUs = 4000;

struct Report {
    int64_t sensed = 0;   // host µs
    int64_t arrived = 0;  // read by the host, µs
    int64_t placed = 0;   // SenseClock's
    bool after_drop = false;
    bool starved = false;  // read in a starved reader's drain (starved_link)
};

// The simulated link of the header: `seconds` of reports, with drops every ~`drop_every`.
std::vector<Report> bursty_link(double seconds, int drop_every, uint32_t seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    std::vector<Report> queued;
    const double device_period = kPeriodUs * (1.0 + 80e-6);
    bool dropped = false;
    for (int64_t i = 0; static_cast<double>(i) * device_period < seconds * 1e6; ++i) {
        if (drop_every > 0 && i > 0 && static_cast<int>(unit(rng) * drop_every) == 0) {
            dropped = true;
            continue;
        }
        Report r;
        r.sensed = std::llround(100'000.0 + static_cast<double>(i) * device_period);
        r.arrived = r.sensed + 1000 + static_cast<int64_t>(unit(rng) * 1000);  // in the queue
        r.after_drop = dropped;
        dropped = false;
        queued.push_back(r);
    }
    // The reader: poll() wakes it when a report is queued, 0..0.5 ms later; 1 time in 50 it
    // oversleeps by 10..110 ms. It reads everything queued then.
    std::vector<Report> out;
    std::size_t next = 0;
    int64_t now = 0;
    while (next < queued.size()) {
        now = std::max(now, queued[next].arrived) + static_cast<int64_t>(unit(rng) * 500);
        if (unit(rng) < 0.02) now += 10'000 + static_cast<int64_t>(unit(rng) * 100'000);
        while (next < queued.size() && queued[next].arrived <= now) {
            Report r = queued[next++];
            r.arrived = now;  // read in this drain
            out.push_back(r);
        }
        now += 50;  // the drain's handling
    }
    return out;
}

// Drains (runs of equal read times) through the clock. Returns the period it first learned.
double place_all(SenseClock& clock, std::vector<Report>& reports) {
    double learned_period = 0;
    std::size_t i = 0;
    while (i < reports.size()) {
        std::size_t j = i;
        std::vector<int64_t> arrivals;
        while (j < reports.size() && reports[j].arrived == reports[i].arrived) arrivals.push_back(reports[j++].arrived);
        std::vector<int64_t> sense(arrivals.size());
        clock.place(arrivals, sense);
        if (learned_period == 0 && clock.learned()) learned_period = clock.period_us();
        for (std::size_t k = 0; k < sense.size(); ++k) reports[i + k].placed = sense[k];
        i = j;
    }
    return learned_period;
}

constexpr std::size_t kSettled = 750;  // reports (3 s): learning and the first period fit are behind

TEST(SenseClock, BurstsAreSpreadBackOverThePeriodsTheyWereSensedIn) {
    for (const uint32_t seed : {1u, 2u, 3u}) {
        SCOPED_TRACE("seed " + std::to_string(seed));
        std::vector<Report> reports = bursty_link(12.0, 0, seed);
        SenseClock clock;
        place_all(clock, reports);
        ASSERT_TRUE(clock.learned());
        EXPECT_NEAR(clock.period_us(), kPeriodUs * (1.0 + 80e-6), 0.002 * kPeriodUs);
        int off = 0, arrival_off = 0, intervals = 0;
        for (std::size_t i = kSettled; i < reports.size(); ++i) {
            const double truth = static_cast<double>(reports[i].sensed - reports[i - 1].sensed);
            off += std::abs(static_cast<double>(reports[i].placed - reports[i - 1].placed) - truth) > 0.01 * kPeriodUs;
            arrival_off += std::abs(static_cast<double>(reports[i].arrived - reports[i - 1].arrived) - truth) > 0.25 * kPeriodUs;
            ++intervals;
        }
        EXPECT_EQ(off, 0) << "of " << intervals << " intervals";
        EXPECT_GT(arrival_off, intervals / 20) << "the link is not bursty enough to show anything";
        EXPECT_EQ(clock.slots_skipped(), 0);
    }
}

TEST(SenseClock, DropsAreSkippedOnceTheWindowShowsThem) {
    std::vector<Report> reports = bursty_link(12.0, 200, 7);
    SenseClock clock;
    place_all(clock, reports);
    int drops = 0, off = 0;
    for (std::size_t i = kSettled; i < reports.size(); ++i) {
        drops += reports[i].after_drop ? 1 : 0;
        const double truth = static_cast<double>(reports[i].sensed - reports[i - 1].sensed);
        // The period reads long by the drop rate (the fit counts reports): 0.5% here.
        off += std::abs(static_cast<double>(reports[i].placed - reports[i - 1].placed) - truth) > 0.02 * kPeriodUs;
    }
    ASSERT_GT(drops, 5);

    EXPECT_LE(off, 2 * drops);
    // No drift: the placed times stay within a window of evidence of the truth's offset.
    const int64_t offset = reports.back().placed - reports.back().sensed;
    for (std::size_t i = kSettled; i < reports.size(); ++i)
        EXPECT_NEAR(static_cast<double>(reports[i].placed - reports[i].sensed), static_cast<double>(offset),
                    SenseClock::kWindowUs + 2.0 * kPeriodUs)
            << "report " << i;
}

TEST(SenseClock, ASilentDeviceIsReanchoredByItsNextReport) {
    SenseClock clock;
    int64_t t = 0;
    for (int i = 0; i < 200; ++i, t += kPeriodUs) {
        const int64_t a = t + 1000;
        int64_t s = 0;
        clock.place(std::span<const int64_t>(&a, 1), std::span<int64_t>(&s, 1));
    }
    ASSERT_TRUE(clock.learned());
    const int64_t before = clock.last_sense_us();
    // Two seconds of silence, then reports again: the next one sits near its arrival.
    t += 2'000'000;
    const int64_t a = t + 1000;
    int64_t s = 0;
    clock.place(std::span<const int64_t>(&a, 1), std::span<int64_t>(&s, 1));
    EXPECT_NEAR(static_cast<double>(s - before), 2'004'000.0, kPeriodUs);
}

// A starved host (the VM's pid-emulation check under load: 405 reports in one drain, for
// 374 of the gadget's ticks, stale ones among them): the link of the header with a reader
// that, from `starve_from` on, every `starve_every` seconds sleeps `starve_s` seconds and
// then reads, with everything queued, `stale` copies of the last reports it had read before
// (each with its true sense time: old). During the first `slow_learning_s` seconds the device
// sends only every other tick (a starved gadget skipping ticks while the clock learns: the
// period learned is twice the device's). Truth: the sense and read times.
std::vector<Report> starved_link(double seconds, double slow_learning_s, double starve_from, double starve_every,
                                 double starve_s, int stale, uint32_t seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    std::vector<Report> queued;
    for (int64_t i = 0; static_cast<double>(i) * kPeriodUs < seconds * 1e6; ++i) {
        if (static_cast<double>(i) * kPeriodUs < slow_learning_s * 1e6 && i % 2 == 1) continue;
        Report r;
        r.sensed = 100'000 + i * kPeriodUs;
        r.arrived = r.sensed + 1000 + static_cast<int64_t>(unit(rng) * 1000);
        queued.push_back(r);
    }
    std::vector<Report> out;
    std::size_t next = 0;
    int64_t now = 0;
    double next_starve = starve_from * 1e6;
    while (next < queued.size()) {
        now = std::max(now, queued[next].arrived) + static_cast<int64_t>(unit(rng) * 500);
        const bool starved = starve_every > 0 && static_cast<double>(now) >= next_starve;
        if (starved) {
            now += static_cast<int64_t>(starve_s * 1e6);
            next_starve += starve_every * 1e6;
            const std::size_t read_before = out.size();
            for (std::size_t k = read_before - std::min<std::size_t>(read_before, static_cast<std::size_t>(stale));
                 k < read_before; ++k) {
                Report copy = out[k];  // a stale copy, read again
                copy.arrived = now;
                copy.starved = true;
                out.push_back(copy);
            }
        } else if (unit(rng) < 0.02) {
            now += 10'000 + static_cast<int64_t>(unit(rng) * 100'000);
        }
        while (next < queued.size() && queued[next].arrived <= now) {
            Report r = queued[next++];
            r.arrived = now;
            r.starved = starved;
            out.push_back(r);
        }
        now += 50;
    }
    return out;
}

// What the bound promises on any sequence: sense times strictly increasing, none more than
// kMaxLeadUs after its arrival. Returns the largest lead seen.
int64_t expect_lead_bounded(const std::vector<Report>& reports) {
    int64_t most = INT64_MIN;
    for (std::size_t i = 0; i < reports.size(); ++i) {
        most = std::max(most, reports[i].placed - reports[i].arrived);
        EXPECT_LE(reports[i].placed - reports[i].arrived, SenseClock::kMaxLeadUs) << "report " << i;
        if (i > 0) {
            EXPECT_GT(reports[i].placed, reports[i - 1].placed) << "report " << i;
        }
    }
    return most;
}

TEST(SenseClock, APeriodLearnedTooLongNeverRunsTheClockAheadOfTheArrivals) {
    // Learned over a second in which the device sent every other tick: T reads 8 ms where the
    // device reports every 4 ms. Unbounded, each report would put its slot 4 ms further
    // ahead of its arrival: 250 reports a second, a second of lead every second.
    std::vector<Report> reports = starved_link(12.0, 1.0, 0, 0, 0, 0, 5);
    SenseClock clock;
    const double learned_period = place_all(clock, reports);
    ASSERT_GT(learned_period, 1.5 * kPeriodUs) << "the scenario: a period learned far too long";
    const int64_t most = expect_lead_bounded(reports);
    std::printf("[ measured ] period learned %.0f us, in the end %.1f us; the largest lead %lld us; %lld drains "
                "compressed\n",
                learned_period, clock.period_us(), static_cast<long long>(most),
                static_cast<long long>(clock.drains_compressed()));
    EXPECT_GT(clock.drains_compressed(), 0);
    // The period is corrected (the fit, let through once drains had to be compressed), and
    // then the grid's properties hold again: the last 4 s, intervals as the truth's.
    EXPECT_NEAR(clock.period_us(), kPeriodUs, 0.002 * kPeriodUs);
    int off = 0, intervals = 0;
    for (std::size_t k = 1; k < reports.size(); ++k) {
        if (reports[k].sensed < reports.back().sensed - 4'000'000) continue;
        const double truth = static_cast<double>(reports[k].sensed - reports[k - 1].sensed);
        off += std::abs(static_cast<double>(reports[k].placed - reports[k - 1].placed) - truth) > 0.01 * kPeriodUs;
        ++intervals;
    }
    EXPECT_EQ(off, 0) << "of " << intervals << " intervals";
}

TEST(SenseClock, DrainsHoldingStaleReportsNeverRunTheClockAheadForGood) {
    // Every 2.5 s from 3 s on, the reader sleeps 1.5 s and then reads the 375 reports
    // queued and 40 stale copies: a drain holding 40 reports more than periods have passed.
    // Unbounded, each such drain left 160 ms of lead over the arrivals for good.
    constexpr int kStale = 40;
    std::vector<Report> reports = starved_link(16.0, 0, 3.0, 2.5, 1.5, kStale, 9);
    SenseClock clock;
    place_all(clock, reports);
    ASSERT_TRUE(clock.learned());
    const int64_t most = expect_lead_bounded(reports);
    std::printf("[ measured ] the largest lead %lld us; %lld drains compressed; period %.1f us\n",
                static_cast<long long>(most), static_cast<long long>(clock.drains_compressed()),
                clock.period_us());
    EXPECT_GE(clock.drains_compressed(), 4);
    // Against the truth: outside the starved drains (whose reports are spread over the time
    // there was, stale ones first), the offset of sense over truth (placed − sensed) stays
    // within the bound of where it was before the first starvation: it does not add up,
    // drain by drain.
    int64_t before = 0;
    for (const Report& r : reports)
        if (r.arrived < 3'000'000) before = r.placed - r.sensed;
    int64_t worst = 0;
    for (std::size_t k = 0; k < reports.size(); ++k) {
        if (reports[k].starved) continue;
        worst = std::max(worst, reports[k].placed - reports[k].sensed - before);
        EXPECT_LE(reports[k].placed - reports[k].sensed - before, SenseClock::kMaxLeadUs) << "report " << k;
    }
    std::printf("[ measured ] offset over the truth's, outside the starved drains: at most %lld us more than "
                "before the first starvation\n",
                static_cast<long long>(worst));
}

// The host's engine at three sets of times for the same sensed positions: a wall swept by
// the VM's sine (x = 2000·sin(πt), through the wall at 0, free side x < 0).
std::vector<float> render_wall(const std::vector<Report>& reports, int which) {
    const sim::DeviceProfile& profile = *sim::find_device_profile("iforce2");
    DeviceCaps caps;
    caps.device = "iforce2";
    caps.axis_count = profile.axis_count;
    caps.axes[0].sensor_counts = profile.axes[0].sensor_counts;
    HostRenderer renderer(host_engine_config(caps));
    const CreateResult r = renderer.create(wall_on_x(2000));
    (void)renderer.start(r.id, HostRenderer::kOwnIterations, false);
    const double q = 2.0 * kFullScale / profile.axes[0].sensor_counts;
    std::vector<float> out;
    for (const Report& rep : reports) {
        const double t = static_cast<double>(rep.sensed) * 1e-6;
        // The sensor's counts, as the report carries them (whole units).
        const float x = static_cast<float>(std::lround(std::floor(2000.0 * std::sin(M_PI * t) / q) * q));
        const int64_t at = which == 0 ? rep.sensed : which == 1 ? rep.placed : rep.arrived;
        out.push_back(renderer.render(at, std::span<const float>(&x, 1), 0, 0).force[0]);
    }
    return out;
}

TEST(SenseClock, TheHostsWallAtSenseTimesIsTheWallAtTrueTimes) {
    std::vector<Report> reports = bursty_link(8.0, 0, 11);
    SenseClock clock;
    place_all(clock, reports);
    const std::vector<float> truth = render_wall(reports, 0);
    const std::vector<float> sensed = render_wall(reports, 1);
    const std::vector<float> arrived = render_wall(reports, 2);
    double worst_sensed = 0, worst_arrived = 0;
    for (std::size_t i = kSettled; i < reports.size(); ++i) {
        worst_sensed = std::max(worst_sensed, std::abs(double(sensed[i]) - truth[i]));
        worst_arrived = std::max(worst_arrived, std::abs(double(arrived[i]) - truth[i]));
    }
    std::printf("[ measured ] wall force vs true times: sense clock %.1f units, arrival stamps %.1f units\n",
                worst_sensed, worst_arrived);
    // The same samples at the same spacing (the offset aside): the same force, to the
    // period fit's last fraction of a percent of the velocity (1 unit of rounding).
    EXPECT_LE(worst_sensed, 1.0);
    EXPECT_GT(worst_arrived, 100.0);
}

}  // namespace
}  // namespace feel::host::emulation
