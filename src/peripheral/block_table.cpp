// The effect block table (block_table.hpp).
#include "block_table.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace feel::peripheral::detail {

BlockTable::BlockTable(int32_t capacity, int32_t engine_slots) {
    if (capacity < 1 || capacity > 65535) {
        throw std::invalid_argument("effect blocks = " + std::to_string(capacity) +
                                    " is out of range (allowed 1..65535)");
    }
    if (engine_slots < 1 || engine_slots > 65535) {
        throw std::invalid_argument("engine effect slots = " + std::to_string(engine_slots) +
                                    " is out of range (allowed 1..65535)");
    }
    blocks_.resize(static_cast<std::size_t>(capacity));
    block_of_slot_.assign(static_cast<std::size_t>(engine_slots), 0);
}

uint16_t BlockTable::allocate(EffectType type, uint16_t sample_count) {
    for (std::size_t i = 0; i < blocks_.size(); ++i) {
        if (blocks_[i]) continue;
        auto block = std::make_unique<Block>();
        block->type = type;
        block->sample_count = sample_count;
        block->shadow.type = type;
        block->committed.type = type;
        blocks_[i] = std::move(block);
        ++allocated_;
        return static_cast<uint16_t>(i + 1);
    }
    return 0;
}

Block* BlockTable::find(uint32_t index) noexcept {
    return in_range(index) ? blocks_[index - 1].get() : nullptr;
}

const Block* BlockTable::find(uint32_t index) const noexcept {
    return in_range(index) ? blocks_[index - 1].get() : nullptr;
}

void BlockTable::commit(uint16_t index, EffectId effect) noexcept {
    Block* b = find(index);
    if (b == nullptr) return;
    if (!b->is_committed) ++committed_;
    b->is_committed = true;
    b->effect = effect;
    if (effect.index < block_of_slot_.size()) block_of_slot_[effect.index] = index;
}

void BlockTable::free(uint16_t index) noexcept {
    Block* b = find(index);
    if (b == nullptr) return;
    if (b->is_committed) {
        --committed_;
        if (b->effect.index < block_of_slot_.size() && block_of_slot_[b->effect.index] == index) {
            block_of_slot_[b->effect.index] = 0;
        }
    }
    blocks_[index - 1].reset();
    --allocated_;
}

void BlockTable::clear() noexcept {
    for (auto& b : blocks_) b.reset();
    std::fill(block_of_slot_.begin(), block_of_slot_.end(), uint16_t{0});
    allocated_ = 0;
    committed_ = 0;
}

uint16_t BlockTable::block_of(EffectId effect) const noexcept {
    if (!effect.valid() || effect.index >= block_of_slot_.size()) return 0;
    const uint16_t index = block_of_slot_[effect.index];
    const Block* b = find(index);
    return b != nullptr && b->is_committed && b->effect == effect ? index : 0;
}

}  // namespace feel::peripheral::detail
