// feel.h: calls that never stall a frame — feel_queue over feel::host::CommandQueue.
// A queued call returns its ticket, or 0 with the thread's last error set when refused at
// once; outcomes reach the caller's callback at feel_queue_poll, on its own thread.
#include <chrono>

#include "capi_internal.hpp"
#include "feel/host/command_queue.hpp"

struct feel_queue {
    explicit feel_queue(feel::host::Device device, feel::host::CommandQueueOptions options)
        : queue(std::move(device), options) {}
    feel::host::CommandQueue queue;
};

namespace feel::capi {
namespace {

// Runs body() -> Result<Ticket> under guard(); the ticket, or 0 with the error recorded.
template <class Body>
uint64_t queued(const char* function, Body&& body) noexcept {
    uint64_t ticket = 0;
    (void)guard(function, [&] {
        host::Result<host::Ticket> t = body();
        if (!t) return fail(t.status());
        ticket = t.value();
        return succeed();
    });
    return ticket;
}

// The checks every effect call starts with; FEEL_OK or the recorded error.
int check_queue_effect(const char* function, const feel_queue* queue, const feel_effect* effect) noexcept {
    if (!queue) return null_argument(function, "queue");
    if (!effect) return null_argument(function, "effect");
    return FEEL_OK;
}

}  // namespace
}  // namespace feel::capi

using namespace feel::capi;

extern "C" {

feel_queue* feel_queue_create(feel_device* device, int32_t max_pending, int32_t max_outcomes) {
    return guard_ptr<feel_queue>("feel_queue_create", [&]() -> feel_queue* {
        if (!device) return no_handle(null_argument("feel_queue_create", "device"));
        if (max_pending < 0 || max_pending > 65536) {
            return no_handle(out_of_range("feel_queue_create", "max_pending", max_pending, 0, 65536));
        }
        if (max_outcomes < 0 || max_outcomes > 1048576) {
            return no_handle(out_of_range("feel_queue_create", "max_outcomes", max_outcomes, 0, 1048576));
        }
        feel::host::CommandQueueOptions o;
        if (max_pending) o.max_pending = static_cast<std::size_t>(max_pending);
        if (max_outcomes) o.max_outcomes = static_cast<std::size_t>(max_outcomes);
        return new feel_queue(device->device, o);
    });
}

void feel_queue_destroy(feel_queue* queue) {
    (void)guard("feel_queue_destroy", [&] {
        delete queue;
        return succeed();
    });
}

uint64_t feel_queue_start(feel_queue* queue, feel_effect* effect, int32_t iterations, bool solo) {
    return queued("feel_queue_start", [&]() -> feel::host::Result<feel::host::Ticket> {
        if (check_queue_effect("feel_queue_start", queue, effect) != FEEL_OK) throw_last_error();
        return queue->queue.start(*effect->effect, iterations, solo);
    });
}

uint64_t feel_queue_stop(feel_queue* queue, feel_effect* effect) {
    return queued("feel_queue_stop", [&]() -> feel::host::Result<feel::host::Ticket> {
        if (check_queue_effect("feel_queue_stop", queue, effect) != FEEL_OK) throw_last_error();
        return queue->queue.stop(*effect->effect);
    });
}

uint64_t feel_queue_set_parameters(feel_queue* queue, feel_effect* effect, const feel_effect_params* params,
                                   uint32_t field_mask, bool restart, const int16_t* samples, int32_t sample_count) {
    return queued("feel_queue_set_parameters", [&]() -> feel::host::Result<feel::host::Ticket> {
        const char* fn = "feel_queue_set_parameters";
        if (check_queue_effect(fn, queue, effect) != FEEL_OK) throw_last_error();
        feel_effect_params in{};
        if (read_in(fn, "params", params, in) != FEEL_OK) throw_last_error();
        const feel::EffectParams p = to_cpp(fn, in);
        return queue->queue.set_parameters(*effect->effect, p, field_mask, restart,
                                           samples_of(fn, samples, sample_count));
    });
}

uint64_t feel_queue_set_gain(feel_queue* queue, int32_t gain) {
    return queued("feel_queue_set_gain", [&]() -> feel::host::Result<feel::host::Ticket> {
        if (!queue) {
            null_argument("feel_queue_set_gain", "queue");
            throw_last_error();
        }
        return queue->queue.set_gain(gain);
    });
}

uint64_t feel_queue_command(feel_queue* queue, int32_t command) {
    return queued("feel_queue_command", [&]() -> feel::host::Result<feel::host::Ticket> {
        if (!queue) {
            null_argument("feel_queue_command", "queue");
            throw_last_error();
        }
        if (command < FEEL_COMMAND_ACTUATORS_ON || command > FEEL_COMMAND_RESUME) {
            out_of_range("feel_queue_command", "command", command, FEEL_COMMAND_ACTUATORS_ON, FEEL_COMMAND_RESUME);
            throw_last_error();
        }
        return queue->queue.command(static_cast<feel::runtime::DeviceControl>(command));
    });
}

uint64_t feel_queue_stream_force(feel_queue* queue, const int32_t* force, int32_t axis_count) {
    return queued("feel_queue_stream_force", [&]() -> feel::host::Result<feel::host::Ticket> {
        if (!queue) {
            null_argument("feel_queue_stream_force", "queue");
            throw_last_error();
        }
        if (!force) {
            null_argument("feel_queue_stream_force", "force");
            throw_last_error();
        }
        if (axis_count < 1 || axis_count > FEEL_MAX_AXES) {
            out_of_range("feel_queue_stream_force", "axis_count", axis_count, 1, FEEL_MAX_AXES);
            throw_last_error();
        }
        return queue->queue.stream_force(std::span<const int32_t>(force, static_cast<std::size_t>(axis_count)));
    });
}

int32_t feel_queue_poll(feel_queue* queue, feel_outcome_callback callback, void* user_data) {
    int32_t count = 0;
    (void)guard("feel_queue_poll", [&] {
        if (!queue) return null_argument("feel_queue_poll", "queue");
        if (!callback) return null_argument("feel_queue_poll", "callback");
        const std::size_t n = queue->queue.poll([&](const feel::host::Outcome& o) {
            feel_outcome out{};
            out.size = sizeof out;
            out.ticket = o.ticket;
            out.what = o.what;
            out.code = static_cast<int32_t>(o.status.kind);
            out.message = o.status.message.c_str();
            out.coalesced = o.coalesced;
            out.into = o.into;
            callback(&out, user_data);
        });
        count = static_cast<int32_t>(n);
        return succeed();
    });
    return count;
}

int feel_queue_flush(feel_queue* queue, int32_t timeout_ms) {
    return guard("feel_queue_flush", [&] {
        if (!queue) return null_argument("feel_queue_flush", "queue");
        if (timeout_ms < 1 || timeout_ms > 60000) return out_of_range("feel_queue_flush", "timeout_ms", timeout_ms, 1, 60000);
        return from_status(queue->queue.flush(std::chrono::milliseconds(timeout_ms)));
    });
}

int32_t feel_queue_pending(const feel_queue* queue) {
    int32_t n = 0;
    (void)guard("feel_queue_pending", [&] {
        if (!queue) return null_argument("feel_queue_pending", "queue");
        n = static_cast<int32_t>(queue->queue.pending());
        return succeed();
    });
    return n;
}

}  // extern "C"
