// The device's effect blocks: PID Effect Block Index 1..capacity <-> runtime EffectId.
//
// A block is allocated by Create New Effect for one effect type and freed by Block Free or
// a device reset. Until its first accepted Set Effect it exists only here: the host fills
// its shadow parameters block by block (Set Condition, Set Periodic, ...). The accepted
// Set Effect creates the effect in the engine (the block is then committed and knows its
// EffectId); later ones update it. The table is allocated once (capacity entries); each
// block's parameters are allocated when the block is, so memory follows the blocks in use
// and never exceeds capacity of them.
#pragma once

#include <cstdint>
#include <memory>
#include <vector>

#include "feel/effect.hpp"
#include "feel/engine.hpp"

namespace feel::peripheral::detail {

// Which of a block's type-specific reports arrived since the block was allocated (or since
// its last refused commit, which rolls them back). A first commit needs the ones its type
// uses; docs/peripheral.md lists them.
struct Arrivals {
    uint8_t conditions = 0;    // bit i: Set Condition for the effect's axis i
    uint8_t control_laws = 0;  // bit i: Set Control Law for axis i
    bool periodic = false;
    bool sweep = false;
    bool constant = false;
    bool ramp = false;
    bool custom = false;       // Set Custom Force
    bool texture = false;
    bool wall = false;
    bool barrier = false;
    bool dynamic = false;
    bool envelope = false;
};

struct Block {
    EffectType type = EffectType::constant;
    uint16_t sample_count = 0;     // Create New Effect's byte count, in samples (force profiles)
    EffectParams shadow{};         // what the next Set Effect commits
    EffectParams committed{};      // what the engine holds (when is_committed)
    Arrivals arrived{};
    bool is_committed = false;
    EffectId effect{};             // the runtime's handle (when is_committed)
    bool host_saw_playing = false; // the playing flag of the last PidState sent for it
};

class BlockTable {
public:
    // capacity: blocks 1..capacity (the device's effect slots). engine_slots: the engine's
    // max_effects, the range of EffectId::index.
    BlockTable(int32_t capacity, int32_t engine_slots);

    [[nodiscard]] int32_t capacity() const noexcept { return static_cast<int32_t>(blocks_.size()); }
    [[nodiscard]] bool in_range(uint32_t index) const noexcept {
        return index >= 1 && index <= blocks_.size();
    }
    // The lowest free block for a new effect of this type, 0 when every block is in use.
    uint16_t allocate(EffectType type, uint16_t sample_count);
    // The allocated block, nullptr for a free or out-of-range index.
    [[nodiscard]] Block* find(uint32_t index) noexcept;
    [[nodiscard]] const Block* find(uint32_t index) const noexcept;
    // Marks a block created in the engine as `effect`.
    void commit(uint16_t index, EffectId effect) noexcept;
    void free(uint16_t index) noexcept;
    void clear() noexcept;

    // The block of a runtime effect, 0 when none of the blocks holds it.
    [[nodiscard]] uint16_t block_of(EffectId effect) const noexcept;

    [[nodiscard]] int32_t allocated() const noexcept { return allocated_; }
    [[nodiscard]] int32_t committed() const noexcept { return committed_; }

private:
    std::vector<std::unique_ptr<Block>> blocks_;  // [index - 1]; null when free
    std::vector<uint16_t> block_of_slot_;         // EffectId::index -> block, 0 for none
    int32_t allocated_ = 0;
    int32_t committed_ = 0;
};

}  // namespace feel::peripheral::detail
