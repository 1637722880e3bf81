// Counting instructions on the emulated Cortex-M4 (qemu-system-arm -M mps2-an386).
//
// qemu 7.2 does not model the DWT cycle counter (it reads 0). Run with `-icount shift=0`
// and every instruction advances qemu's virtual clock by 1 ns; SysTick, clocked by the
// board's 25 MHz processor clock, then counts down once per 40 instructions. So
// instructions ≈ 40 × SysTick counts, to within 40 per reading. SysTick is 24 bits: one
// reading spans at most 2^24 counts (671 M instructions), far more than a tick.
#pragma once

#include <cstdint>

namespace feel::firmware {

class InstructionCounter {
public:
    static constexpr uint32_t kInstructionsPerCount = 40;

    InstructionCounter() noexcept {
        reg(kReload) = 0x00FF'FFFFu;
        reg(kCurrent) = 0;
        reg(kControl) = 0x5u;  // enable, processor clock, no interrupt
    }
    // SysTick counts down; the counts between two readings, modulo 2^24.
    [[nodiscard]] static uint32_t now() noexcept { return reg(kCurrent); }
    [[nodiscard]] static uint32_t counts_since(uint32_t before) noexcept { return (before - now()) & 0x00FF'FFFFu; }

private:
    static constexpr uintptr_t kControl = 0xE000'E010u, kReload = 0xE000'E014u, kCurrent = 0xE000'E018u;
    static volatile uint32_t& reg(uintptr_t address) noexcept { return *reinterpret_cast<volatile uint32_t*>(address); }
};

}  // namespace feel::firmware
