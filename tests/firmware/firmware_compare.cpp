// The Cortex-M4F build against the x86 build (issue 14): renders firmware/scenario.hpp's
// fixed scenario here and compares every tick's forces with the lines "F n x y" (hex bits
// of the floats) that firmware/m4_test.cpp printed on the emulated board. Passes when every
// force is within 1 unit; says how many ticks match bit for bit, the largest difference and
// the instruction counts the board reported.
//
//   feel_firmware_compare QEMU_OUTPUT
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

#include "feel/engine.hpp"
#include "scenario.hpp"

namespace {

float from_bits(uint32_t b) {
    float f;
    std::memcpy(&f, &b, sizeof f);
    return f;
}

}  // namespace

int main(int argc, char** argv) {
    if (argc != 2) {
        std::cerr << "usage: feel_firmware_compare QEMU_OUTPUT\n";
        return 2;
    }
    std::ifstream file(argv[1]);
    if (!file) {
        std::cerr << "cannot read " << argv[1] << "\n";
        return 2;
    }
    std::vector<float> board_x(feel::firmware::kScenarioTicks + 1, NAN), board_y(board_x);
    std::string line;
    bool done = false;
    while (std::getline(file, line)) {
        if (line.rfind("F ", 0) == 0) {
            std::istringstream in(line.substr(2));
            int n = 0;
            std::string x, y;
            in >> n >> x >> y;
            if (n < 1 || n > feel::firmware::kScenarioTicks) {
                std::cerr << "tick out of range 1.." << feel::firmware::kScenarioTicks << ": " << line << "\n";
                return 1;
            }
            board_x[n] = from_bits(static_cast<uint32_t>(std::stoul(x, nullptr, 16)));
            board_y[n] = from_bits(static_cast<uint32_t>(std::stoul(y, nullptr, 16)));
        } else {
            if (line == "done") done = true;
            std::cout << "board: " << line << "\n";
        }
    }
    if (!done) {
        std::cerr << "the board's output is incomplete (no \"done\")\n";
        return 1;
    }

    feel::Engine engine(feel::firmware::scenario_config());
    if (!feel::firmware::load_scenario(engine)) {
        std::cerr << "the x86 engine refused the scenario\n";
        return 1;
    }
    feel::TickInput in;
    feel::TickOutput out;
    feel::DynamicReport report;
    int identical = 0, within = 0;
    double worst = 0;
    int worst_tick = 0;
    for (int n = 1; n <= feel::firmware::kScenarioTicks; ++n) {
        feel::firmware::scenario_handle(in, n);
        engine.tick(in, out);
        while (engine.pop_report(report)) {
        }
        const double dx = std::fabs(static_cast<double>(out.force[0]) - board_x[n]);
        const double dy = std::fabs(static_cast<double>(out.force[1]) - board_y[n]);
        const double d = std::isnan(dx) || std::isnan(dy) ? INFINITY : std::max(dx, dy);
        if (std::memcmp(&out.force[0], &board_x[n], 4) == 0 && std::memcmp(&out.force[1], &board_y[n], 4) == 0) {
            ++identical;
        }
        if (d <= 1.0) ++within;
        if (!(d <= worst)) {
            worst = d;
            worst_tick = n;
        }
    }
    std::printf("x86 vs Cortex-M4F: %d ticks, %d bit for bit, %d within 1 unit, largest difference %g (tick %d)\n",
                feel::firmware::kScenarioTicks, identical, within, worst, worst_tick);
    return within == feel::firmware::kScenarioTicks ? 0 : 1;
}
