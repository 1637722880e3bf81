// Force-profile sample memory: one fixed array, carved into contiguous runs per effect.
//
// The device has a fixed amount of parameter memory (§2.2); profiles cost samples from it.
// Allocation is first fit over the gaps between live runs. When no gap is large enough but
// the free total is, the live runs are slid down to close the gaps (compaction), so that a
// create fails with "device full" only when the memory is truly full. Runs are identified
// by their owner slot, so compaction can tell each owner its new offset.
#pragma once

#include <cstdint>
#include <memory>

namespace feel::detail {

class SamplePool {
public:
    struct Run {
        int32_t offset = 0;
        int32_t count = 0;  // 0: the owner holds no samples
    };

    SamplePool(int32_t capacity, int32_t owners);

    // Reserves `count` samples for `owner` (which must hold none) and copies them in.
    // Returns false, changing nothing, when they do not fit.
    bool allocate(int32_t owner, const int16_t* data, int32_t count) noexcept;
    void release(int32_t owner) noexcept;

    [[nodiscard]] const int16_t* data(int32_t owner) const noexcept;
    [[nodiscard]] int32_t free_samples() const noexcept { return capacity_ - used_; }
    [[nodiscard]] int32_t capacity() const noexcept { return capacity_; }

private:
    [[nodiscard]] bool find_gap(int32_t count, int32_t& offset) const noexcept;
    void compact() noexcept;

    int32_t capacity_;
    int32_t owners_;
    int32_t used_ = 0;
    std::unique_ptr<int16_t[]> samples_;
    std::unique_ptr<Run[]> runs_;  // indexed by owner
};

}  // namespace feel::detail
