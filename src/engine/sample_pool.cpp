#include "sample_pool.hpp"

#include <algorithm>
#include <cstring>

namespace feel::detail {

SamplePool::SamplePool(int32_t capacity, int32_t owners)
    : capacity_(capacity),
      owners_(owners),
      samples_(new int16_t[static_cast<size_t>(capacity > 0 ? capacity : 1)]()),
      runs_(new Run[static_cast<size_t>(owners > 0 ? owners : 1)]()) {}

bool SamplePool::find_gap(int32_t count, int32_t& offset) const noexcept {
    // Candidate starts: 0 and the end of every live run. The lowest one that overlaps no
    // live run wins. O(owners²), fine for the command path and a few hundred slots.
    int32_t best = -1;
    auto try_start = [&](int32_t start) {
        if (start + count > capacity_ || (best >= 0 && start >= best)) return;
        for (int32_t o = 0; o < owners_; ++o) {
            const Run& r = runs_[o];
            if (r.count > 0 && start < r.offset + r.count && r.offset < start + count) return;
        }
        best = start;
    };
    try_start(0);
    for (int32_t o = 0; o < owners_; ++o) {
        if (runs_[o].count > 0) try_start(runs_[o].offset + runs_[o].count);
    }
    offset = best;
    return best >= 0;
}

void SamplePool::compact() noexcept {
    int32_t next = 0;
    for (;;) {
        // The live run with the lowest offset at or above `next` moves down to `next`.
        int32_t lowest = -1;
        for (int32_t o = 0; o < owners_; ++o) {
            const Run& r = runs_[o];
            if (r.count > 0 && r.offset >= next && (lowest < 0 || r.offset < runs_[lowest].offset)) lowest = o;
        }
        if (lowest < 0) return;
        Run& r = runs_[lowest];
        if (r.offset != next) {
            std::memmove(&samples_[next], &samples_[r.offset], static_cast<size_t>(r.count) * sizeof(int16_t));
            r.offset = next;
        }
        next += r.count;
    }
}

bool SamplePool::allocate(int32_t owner, const int16_t* data, int32_t count) noexcept {
    if (count <= 0) return true;
    if (owner < 0 || owner >= owners_ || runs_[owner].count != 0 || count > free_samples()) return false;
    int32_t offset = 0;
    if (!find_gap(count, offset)) {
        compact();
        if (!find_gap(count, offset)) return false;
    }
    std::memcpy(&samples_[offset], data, static_cast<size_t>(count) * sizeof(int16_t));
    runs_[owner] = Run{offset, count};
    used_ += count;
    return true;
}

void SamplePool::release(int32_t owner) noexcept {
    if (owner < 0 || owner >= owners_) return;
    used_ -= runs_[owner].count;
    runs_[owner] = Run{};
}

const int16_t* SamplePool::data(int32_t owner) const noexcept {
    return &samples_[runs_[owner].offset];
}

}  // namespace feel::detail
