// A fixed number of records of one kind, handed out by index.
//
// The engine keeps an effect's memory between ticks (a dynamic's simulated mass, a
// friction's bristles, a wall's contact ledger) in pools like this one, not in every effect
// slot: most effects (waves, springs, dampers) keep none, and the largest memory, a
// dynamic's, is twice a condition's. Each pool's capacity is an EngineConfig field
// (max_dynamics, max_stateful_conditions), fixed when the engine is made; a create that
// finds its pool full is refused with device_full (issue 14: RAM on a Cortex-M4F).
//
// Real-time safe after construction: acquire and release are O(1) (a stack of free
// indices), never allocate.
#pragma once

#include <cstdint>
#include <memory>

namespace feel::detail {

inline constexpr uint16_t kNoRecord = 0xFFFF;

template <class Record>
class RecordPool {
public:
    // capacity: 0..65535 records (kNoRecord is never an index).
    explicit RecordPool(int32_t capacity)
        : capacity_(capacity > 0 ? capacity : 0),
          records_(new Record[static_cast<size_t>(capacity_ > 0 ? capacity_ : 1)]),
          free_(new uint16_t[static_cast<size_t>(capacity_ > 0 ? capacity_ : 1)]),
          free_count_(capacity_) {
        // The lowest indices are handed out first.
        for (int32_t i = 0; i < capacity_; ++i) free_[i] = static_cast<uint16_t>(capacity_ - 1 - i);
    }

    [[nodiscard]] int32_t capacity() const noexcept { return capacity_; }
    [[nodiscard]] int32_t free_count() const noexcept { return free_count_; }

    // A free record's index (its contents as the last user left them), or kNoRecord.
    [[nodiscard]] uint16_t acquire() noexcept { return free_count_ > 0 ? free_[--free_count_] : kNoRecord; }
    void release(uint16_t index) noexcept { free_[free_count_++] = index; }

    Record& operator[](uint16_t index) noexcept { return records_[index]; }
    const Record& operator[](uint16_t index) const noexcept { return records_[index]; }

private:
    int32_t capacity_;
    std::unique_ptr<Record[]> records_;
    std::unique_ptr<uint16_t[]> free_;
    int32_t free_count_;
};

}  // namespace feel::detail
