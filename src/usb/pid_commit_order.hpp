// A standard PID host's order of reports, put into feel's.
//
// feel's device session builds an effect as a transaction: the parameter blocks (Set
// Periodic, Set Condition per axis, Set Envelope, ...) fill the block's shadow, and Set
// Effect commits it (docs/peripheral.md, "The transaction"); that is the order Windows' PID
// driver and feel's own host send. Linux's hid-pidff sends Set Effect *first* and the
// parameter blocks after it, and when it changes an effect it sends only the blocks that
// changed, often without a Set Effect at all: it treats every block as taking effect on
// its own.
//
// Rather than bend the session's semantics, the USB side reorders. Per effect block it keeps
// the last Set Effect the host sent and:
//   - holds a Set Effect instead of forwarding it at once;
//   - forwards every parameter block at once, and marks its effect block "to commit" when a
//     Set Effect is known for it;
//   - commits (forwards the held, or the last, Set Effect) when the host turns to the effect
//     itself: before an Effect Operation, Block Free, Effect Status Request or Reflex naming
//     the block, before any Device Control (so that a reset follows the commits it
//     overtakes), or when no report named the block for kSettle.
// hid-pidff sends an upload's reports back to back, so they are all in when the host plays
// the effect, or kSettle later. Reports are judged by the block index they carry, never by
// arrival order against ep0's feature reports (a next Create New Effect may overtake them).
//
// The answers to the Set Effects it forwards are the session's, as for any report; a Set
// Effect the host sent is forwarded exactly once per commit (never dropped). Pure: no
// thread, no clock of its own (the caller passes the time).
#pragma once

#include <chrono>
#include <cstdint>
#include <map>
#include <vector>

#include "feel/transport/transport.hpp"

namespace feel::usb::detail {

class PidCommitOrder {
public:
    using Clock = std::chrono::steady_clock;
    static constexpr std::chrono::milliseconds kSettle{500};  // long: under TCG an upload's reports come 100+ ms apart

    // A frame from the host: returns the frames to hand the session, in order.
    [[nodiscard]] std::vector<transport::Frame> on_frame(transport::Frame frame, Clock::time_point now);
    // Time passed: the commits whose blocks settled.
    [[nodiscard]] std::vector<transport::Frame> on_time(Clock::time_point now);
    // The soonest time on_time() may have something to do; Clock::time_point::max() if never.
    [[nodiscard]] Clock::time_point next_deadline() const noexcept;
    // The host went away: forget everything.
    void reset() noexcept;

private:
    struct Block {
        std::vector<uint8_t> set_effect;  // the last Set Effect the host sent for it
        bool dirty = false;               // a commit is owed
        Clock::time_point last{};         // when a report last named the block
    };
    void commit(uint16_t block, std::vector<transport::Frame>& out);
    void commit_all(std::vector<transport::Frame>& out);
    std::map<uint16_t, Block> blocks_;
};

}  // namespace feel::usb::detail
