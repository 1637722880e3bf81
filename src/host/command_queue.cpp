// CommandQueue: the non-blocking host calls (include/feel/host/command_queue.hpp).
//
// Design. The game's thread and one worker thread share a State: a deque of pending
// commands, the command running now, and the outcomes waiting for poll(), all under one
// mutex that is held only to push, pop or swap (never across a device round trip). The
// worker pops the oldest command, runs it through the blocking API (Effect and Device
// serialize their calls inside, so the game may still use them directly), and files its
// outcome(s). An effect's command holds the effect's core and record (shared), not the
// game's Effect object: the game may destroy its Effect while a command waits; the command
// then runs on a record the device no longer holds and reports invalid_handle.
//
// The worker holds the State alive by its own shared_ptr, so the queue's destructor can
// stop it safely even when the last reference to a device goes away on the worker.
#include "feel/host/command_queue.hpp"

#include <algorithm>
#include <condition_variable>
#include <cstddef>
#include <deque>
#include <mutex>
#include <stdexcept>
#include <string>
#include <thread>
#include <utility>
#include <vector>

#include "device_core.hpp"
#include "effect_download.hpp"

namespace feel::host {

namespace {

enum class Kind : uint8_t { start, stop, set_parameters, set_gain, command, stream_force };

const char* kind_name(Kind k) noexcept {
    switch (k) {
        case Kind::start: return "start";
        case Kind::stop: return "stop";
        case Kind::set_parameters: return "set_parameters";
        case Kind::set_gain: return "set_gain";
        case Kind::command: return "command";
        case Kind::stream_force: return "stream_force";
    }
    return "";
}

struct Command {
    Ticket ticket = 0;
    Kind kind = Kind::start;
    std::shared_ptr<DeviceCore> core;      // effect commands
    std::shared_ptr<EffectRecord> record;  // effect commands; null for device commands
    int32_t iterations = 0;
    bool solo = false;
    EffectParams params{};
    uint32_t field_mask = 0;
    bool restart = false;
    std::vector<int16_t> samples;
    int32_t value = 0;                     // gain, or the DeviceControl
    int32_t force[kMaxAxes] = {};
    int32_t axis_count = 0;
    std::vector<Ticket> absorbed;          // coalesced calls this command carries
};

Status refusal(ErrorKind kind, std::string message) { return Status::failure(kind, std::move(message)); }

}  // namespace

struct CommandQueue::State {
    Device device;
    CommandQueueOptions options;
    mutable std::mutex mu;
    std::condition_variable work_cv;   // the worker waits for commands
    std::condition_variable idle_cv;   // flush() waits for the queue to drain
    std::deque<Command> queue;
    bool running = false;              // the worker is running a command
    bool stopping = false;
    Ticket next_ticket = 1;
    std::deque<Outcome> outcomes;
    uint64_t dropped = 0;
    std::thread worker;

    explicit State(Device d, CommandQueueOptions o) : device(std::move(d)), options(o) {}

    Result<Ticket> push(Command c) {
        std::lock_guard lock(mu);
        if (stopping) return refusal(ErrorKind::invalid_handle, std::string(kind_name(c.kind)) + ": the queue is stopping");
        c.ticket = next_ticket;
        if (const std::ptrdiff_t at = coalescible(c); at >= 0) {
            merge_into(c, queue[static_cast<std::size_t>(at)]);
            // The merged command takes the newest place in the queue.
            queue.erase(queue.begin() + at);
        } else if (queue.size() >= options.max_pending) {
            return refusal(ErrorKind::device_full,
                           std::string(kind_name(c.kind)) + ": " + std::to_string(queue.size()) +
                               " commands already wait (CommandQueueOptions::max_pending = " +
                               std::to_string(options.max_pending) + "): poll() and let the device catch up");
        }
        ++next_ticket;
        queue.push_back(std::move(c));
        work_cv.notify_one();
        return queue.back().ticket;
    }

    // The index of the pending command `c` may replace, or -1: the latest queued command
    // for the same effect (set_parameters) or of the same kind (set_gain, stream_force),
    // when it is of c's kind.
    std::ptrdiff_t coalescible(const Command& c) const {
        if (c.kind != Kind::set_parameters && c.kind != Kind::set_gain && c.kind != Kind::stream_force) return -1;
        for (auto i = static_cast<std::ptrdiff_t>(queue.size()) - 1; i >= 0; --i) {
            const Command& q = queue[static_cast<std::size_t>(i)];
            if (c.kind == Kind::set_parameters) {
                if (q.record != c.record) continue;
                return q.kind == Kind::set_parameters ? i : -1;
            }
            if (q.kind == c.kind) return i;
        }
        return -1;
    }

    // c becomes the merged command; `older` is what it replaces.
    static void merge_into(Command& c, Command& older) {
        c.absorbed = std::move(older.absorbed);
        c.absorbed.push_back(older.ticket);
        if (c.kind != Kind::set_parameters) return;  // set_gain, stream_force: the newest value wins
        const bool new_samples = (c.field_mask & effect_field::kTypeSpecific) != 0;
        c.params = merge_parameters(older.params, c.params, c.field_mask);
        if (!new_samples) c.samples = std::move(older.samples);
        c.field_mask |= older.field_mask;
        c.restart = c.restart || older.restart;
    }

    void file(Outcome o) {  // caller holds mu
        if (outcomes.size() >= options.max_outcomes) {
            outcomes.pop_front();
            ++dropped;
        }
        outcomes.push_back(std::move(o));
    }

    Status run(Command& c) {
        switch (c.kind) {
            case Kind::start:
                return DeviceCore::with_effect(c.core, c.record, [&](Effect& e) { return e.start(c.iterations, c.solo); });
            case Kind::stop:
                return DeviceCore::with_effect(c.core, c.record, [&](Effect& e) { return e.stop(); });
            case Kind::set_parameters:
                return DeviceCore::with_effect(c.core, c.record, [&](Effect& e) {
                    return e.set_parameters(c.params, c.field_mask, c.restart, c.samples);
                });
            case Kind::set_gain: return device.set_gain(c.value);
            case Kind::command: return device.command(static_cast<runtime::DeviceControl>(c.value));
            case Kind::stream_force:
                return device.stream_force(std::span<const int32_t>(c.force, static_cast<std::size_t>(c.axis_count)));
        }
        return Status::success();
    }

    static void work(const std::shared_ptr<State>& self) noexcept {
        State& s = *self;
        std::unique_lock lock(s.mu);
        for (;;) {
            s.work_cv.wait(lock, [&] { return s.stopping || !s.queue.empty(); });
            if (s.queue.empty()) return;  // stopping, and everything queued has run
            Command c = std::move(s.queue.front());
            s.queue.pop_front();
            s.running = true;
            lock.unlock();
            Status status;
            try {
                status = s.run(c);
            } catch (const std::exception& e) {
                status = Status::failure(ErrorKind::protocol, std::string(kind_name(c.kind)) + ": " + e.what());
            } catch (...) {
                status = Status::failure(ErrorKind::protocol, std::string(kind_name(c.kind)) + ": an unknown failure");
            }
            // Let go of the effect before taking the lock: the last reference to a core
            // may close its device here.
            c.record.reset();
            c.core.reset();
            lock.lock();
            try {
                for (const Ticket t : c.absorbed) s.file(Outcome{t, kind_name(c.kind), status, true, c.ticket});
                s.file(Outcome{c.ticket, kind_name(c.kind), std::move(status), false, c.ticket});
            } catch (...) {
                ++s.dropped;  // out of memory for an outcome: counted, never lost silently
            }
            s.running = false;
            if (s.queue.empty()) s.idle_cv.notify_all();
        }
    }
};

CommandQueue::CommandQueue(Device device, CommandQueueOptions options) {
    if (options.max_pending < 1 || options.max_pending > 65536) {
        throw std::invalid_argument("CommandQueueOptions::max_pending = " + std::to_string(options.max_pending) +
                                    " is out of range (allowed 1..65536)");
    }
    if (options.max_outcomes < 1 || options.max_outcomes > 1048576) {
        throw std::invalid_argument("CommandQueueOptions::max_outcomes = " + std::to_string(options.max_outcomes) +
                                    " is out of range (allowed 1..1048576)");
    }
    state_ = std::make_shared<State>(std::move(device), options);
    state_->worker = std::thread([self = state_] { State::work(self); });
}

CommandQueue::~CommandQueue() {
    {
        std::lock_guard lock(state_->mu);
        state_->stopping = true;
    }
    state_->work_cv.notify_all();
    if (state_->worker.get_id() == std::this_thread::get_id()) {
        state_->worker.detach();  // cannot happen through the public API; never join oneself
    } else {
        state_->worker.join();
    }
}

namespace {

// The check of an effect command that needs no device: a live handle. (An effect of
// another device runs on its own device, in this queue's order.)
Status check_effect_handle(const Effect& effect, const char* what) {
    if (!DeviceCore::core_of(effect) || !DeviceCore::record_of(effect)) {
        return refusal(ErrorKind::invalid_handle,
                       std::string(what) + ": this Effect is empty (default-constructed or moved from)");
    }
    return Status::success();
}

}  // namespace

Result<Ticket> CommandQueue::start(const Effect& effect, int32_t iterations, bool solo) {
    if (Status s = check_effect_handle(effect, "start"); !s.ok()) return s;
    if (iterations != runtime::kEffectIterations && iterations != kInfiniteIterations &&
        !(iterations >= 1 && iterations <= 254)) {
        const Error e = Error::out_of_range("iterations", iterations, {1, 254});
        return Status::failure(ErrorKind::invalid_parameter,
                               "start: " + e.message() + ", or 0 for the effect's own count, or kInfiniteIterations",
                               e);
    }
    Command c;
    c.kind = Kind::start;
    c.core = DeviceCore::core_of(effect);
    c.record = DeviceCore::record_of(effect);
    c.iterations = iterations;
    c.solo = solo;
    return state_->push(std::move(c));
}

Result<Ticket> CommandQueue::stop(const Effect& effect) {
    if (Status s = check_effect_handle(effect, "stop"); !s.ok()) return s;
    Command c;
    c.kind = Kind::stop;
    c.core = DeviceCore::core_of(effect);
    c.record = DeviceCore::record_of(effect);
    return state_->push(std::move(c));
}

Result<Ticket> CommandQueue::set_parameters(const Effect& effect, const EffectParams& params, uint32_t field_mask,
                                            bool restart, std::span<const int16_t> samples) {
    if (Status s = check_effect_handle(effect, "set_parameters"); !s.ok()) return s;
    if ((field_mask & ~effect_field::kAll) != 0) {
        const Error e = Error::out_of_range("field_mask", field_mask, {0, effect_field::kAll});
        return Status::failure(ErrorKind::invalid_parameter,
                               "set_parameters: " + e.message() + ": bits beyond effect_field::kAll name no field", e);
    }
    if (params.type != effect.type()) {
        return Status::failure(ErrorKind::invalid_parameter,
                               "set_parameters: the type differs from the effect's: an effect's type never changes",
                               Error::invalid("type", "an effect's type never changes: create another effect"));
    }
    Command c;
    c.kind = Kind::set_parameters;
    c.core = DeviceCore::core_of(effect);
    c.record = DeviceCore::record_of(effect);
    c.params = params;
    c.field_mask = field_mask;
    c.restart = restart;
    c.samples.assign(samples.begin(), samples.end());
    return state_->push(std::move(c));
}

Result<Ticket> CommandQueue::set_gain(int32_t gain) {
    if (!range::kLevel.contains(gain)) {
        const Error e = Error::out_of_range("gain", gain, range::kLevel);
        return Status::failure(ErrorKind::invalid_parameter, "set_gain: " + e.message(), e);
    }
    Command c;
    c.kind = Kind::set_gain;
    c.value = gain;
    return state_->push(std::move(c));
}

Result<Ticket> CommandQueue::command(runtime::DeviceControl control) {
    if (static_cast<int>(control) >= runtime::kDeviceControlCount) {
        const Error e = Error::out_of_range("control", static_cast<int>(control), {0, runtime::kDeviceControlCount - 1});
        return Status::failure(ErrorKind::invalid_parameter, "command: " + e.message(), e);
    }
    Command c;
    c.kind = Kind::command;
    c.value = static_cast<int32_t>(control);
    return state_->push(std::move(c));
}

Result<Ticket> CommandQueue::stream_force(std::span<const int32_t> force) {
    const int32_t axes = state_->device.capabilities().axis_count;
    if (static_cast<int64_t>(force.size()) != axes) {
        const Error e = Error::out_of_range("force.size()", static_cast<int64_t>(force.size()), {axes, axes});
        return Status::failure(ErrorKind::invalid_parameter,
                               "stream_force: " + std::to_string(force.size()) + " forces for a " +
                                   std::to_string(axes) + "-axis device (allowed exactly " + std::to_string(axes) + ")",
                               e);
    }
    Command c;
    c.kind = Kind::stream_force;
    c.axis_count = axes;
    std::copy(force.begin(), force.end(), c.force);  // values are checked by stream_force itself
    return state_->push(std::move(c));
}

std::size_t CommandQueue::poll(const std::function<void(const Outcome&)>& on_outcome) {
    std::deque<Outcome> ready;
    {
        std::lock_guard lock(state_->mu);
        ready.swap(state_->outcomes);
    }
    for (const Outcome& o : ready) on_outcome(o);
    return ready.size();
}

Status CommandQueue::flush(std::chrono::milliseconds timeout) {
    std::unique_lock lock(state_->mu);
    if (state_->idle_cv.wait_for(lock, timeout, [&] { return state_->queue.empty() && !state_->running; })) {
        return Status::success();
    }
    return Status::failure(ErrorKind::timeout, "flush: " + std::to_string(state_->queue.size() + (state_->running ? 1 : 0)) +
                                                   " commands still queued or running after " +
                                                   std::to_string(timeout.count()) + " ms");
}

std::size_t CommandQueue::pending() const {
    std::lock_guard lock(state_->mu);
    return state_->queue.size() + (state_->running ? 1 : 0);
}

uint64_t CommandQueue::dropped_outcomes() const {
    std::lock_guard lock(state_->mu);
    return state_->dropped;
}

}  // namespace feel::host
