// A fixed number of records of one kind, handed out one at a time.
//
// The engine keeps an effect's memory between ticks (a dynamic's simulated mass, a
// friction's bristles, a wall's contact ledger) in pools like this one, not in every effect
// slot: most effects (waves, springs, dampers) keep none, and the largest memory, a
// dynamic's, is twice a condition's. A slot points at its record, so the tick reaches it in
// one load. Each pool's capacity is an EngineConfig field
// (max_dynamics, max_stateful_conditions), fixed when the engine is made; a create that
// finds its pool full is refused with device_full (issue 14: RAM on a Cortex-M4F).
//
// Real-time safe after construction: acquire and release are O(1) (a stack of free
// indices), never allocate.
#pragma once

#include <cstdint>
#include <memory>

namespace feel::detail {

template <class Record>
class RecordPool {
public:
    // capacity: 0..65535 records (so the arrays' counts are 16-bit: no overflowing size to test).
    explicit RecordPool(int32_t capacity)
        : capacity_(capacity > 0 ? capacity : 0),
          records_(new Record[static_cast<uint16_t>(capacity_ > 0 ? capacity_ : 1)]()),
          free_(new uint16_t[static_cast<uint16_t>(capacity_ > 0 ? capacity_ : 1)]),
          free_count_(capacity_) {
        // The lowest indices are handed out first.
        for (int32_t i = 0; i < capacity_; ++i) free_[i] = static_cast<uint16_t>(capacity_ - 1 - i);
    }

    [[nodiscard]] int32_t capacity() const noexcept { return capacity_; }
    [[nodiscard]] int32_t free_count() const noexcept { return free_count_; }

    // A free record (its contents as the last user left them), or nullptr if none is free.
    [[nodiscard]] Record* acquire() noexcept { return free_count_ > 0 ? &records_[free_[--free_count_]] : nullptr; }
    // Returns a record acquire() gave.
    void release(Record* record) noexcept {
        free_[free_count_++] = static_cast<uint16_t>(record - records_.get());
    }

private:
    int32_t capacity_;
    std::unique_ptr<Record[]> records_;
    std::unique_ptr<uint16_t[]> free_;
    int32_t free_count_;
};

}  // namespace feel::detail
