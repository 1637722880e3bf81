// feel::host — calls that never stall a game's frame.
//
// Every call of Device and Effect waits for the device's answer: about 1 ms for a start
// and 2 ms for set_parameters, more under load (README, "From a game's call to the
// motors"). A game that must not wait queues its commands here instead. Each call checks
// what it can check at once (an empty effect, the iteration range, the mask, the type, the
// stream's values, a full queue), queues the command and returns a Ticket; one worker
// thread per CommandQueue runs the queued commands in order through the blocking API, and
// their outcomes come back on the game's own thread at its next poll():
//
//   feel::host::CommandQueue queue(device);
//   auto ticket = queue.start(spring);                  // returns in microseconds
//   ...
//   queue.poll([](const feel::host::Outcome& o) {       // once per frame
//       if (!o.status.ok()) log(o.status.message);
//   });
//
// Order. Commands run in the order they were queued, one at a time, so a start queued
// before a stop is applied before it. Use one CommandQueue per device (two queues on one
// device keep their own orders, not a common one), from one thread at a time.
//
// Coalescing. A burst of updates to one effect coalesces to the newest, as a game wants:
// a set_parameters for an effect whose latest queued command is a set_parameters not yet
// running replaces that one (the two masks' fields merged, the newer values winning,
// restart if either asked for it) and moves to the end of the queue. set_gain and
// stream_force coalesce the same way with a pending set_gain or stream sample. Each
// coalesced call still gets its Outcome: `coalesced` is set and `into` is the ticket whose
// command carried it, whose status it shares.
//
// Memory is bounded: at most max_pending commands wait (a call beyond that is refused at
// once, nothing queued), and at most max_outcomes outcomes wait for poll() (older ones are
// dropped and counted). Nothing here is real-time safe: the calls take a mutex held only
// to push or pop a command, and may allocate (a force profile's samples, an error
// message). docs/host-api.md, "Calls that never stall a frame".
#pragma once

#include <chrono>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <memory>
#include <span>

#include "feel/host/device.hpp"

namespace feel::host {

// A queued command's number: 1, 2, 3, ... in the order of the calls.
using Ticket = uint64_t;

// What became of a queued command.
struct Outcome {
    Ticket ticket = 0;
    const char* what = "";    // "start", "stop", "set_parameters", "set_gain", "command", "stream_force"
    Status status;            // what the blocking call returned
    bool coalesced = false;   // folded into a later call of the same kind (see `into`)
    Ticket into = 0;          // the ticket that carried it; == ticket when not coalesced
};

struct CommandQueueOptions {
    std::size_t max_pending = 1024;   // commands waiting to run, 1..65536
    std::size_t max_outcomes = 4096;  // outcomes waiting for poll(), 1..1048576
};

class CommandQueue {
public:
    // Starts the worker thread. Throws std::invalid_argument for options out of range.
    explicit CommandQueue(Device device, CommandQueueOptions options = {});
    // Runs the commands already queued (each bounded by the device's timeout), then stops
    // the worker. Outcomes not polled are dropped.
    ~CommandQueue();
    CommandQueue(const CommandQueue&) = delete;
    CommandQueue& operator=(const CommandQueue&) = delete;

    // The non-blocking forms of Effect::start, stop, set_parameters and Device::set_gain,
    // command, stream_force. The Result is the ticket, or an immediate refusal (nothing
    // queued): invalid_handle for an empty Effect,
    // invalid_parameter for what can be checked without the device, device_full when
    // max_pending commands already wait.
    Result<Ticket> start(const Effect& effect, int32_t iterations = runtime::kEffectIterations, bool solo = false);
    Result<Ticket> stop(const Effect& effect);
    Result<Ticket> set_parameters(const Effect& effect, const EffectParams& params,
                                  uint32_t field_mask = effect_field::kAll, bool restart = false,
                                  std::span<const int16_t> samples = {});
    Result<Ticket> set_gain(int32_t gain);
    Result<Ticket> command(runtime::DeviceControl control);
    Result<Ticket> stream_force(std::span<const int32_t> force);

    // Calls on_outcome on this thread for every command finished since the last poll,
    // in the order they finished; returns how many. Never waits.
    std::size_t poll(const std::function<void(const Outcome&)>& on_outcome);
    // Waits until nothing is queued or running (or the timeout: then `timeout`).
    Status flush(std::chrono::milliseconds timeout);
    // Commands queued or running.
    [[nodiscard]] std::size_t pending() const;
    // Outcomes dropped because max_outcomes waited unpolled.
    [[nodiscard]] uint64_t dropped_outcomes() const;

    struct State;  // shared with the worker thread (command_queue.cpp)

private:
    std::shared_ptr<State> state_;
};

}  // namespace feel::host
