// feel.h: effects (start, stop, status, destroy), dynamic report subscriptions, and the
// two calls of §9.5 (feel_library_load, feel_library_play).
#include <filesystem>
#include <utility>

#include "capi_internal.hpp"

namespace feel::capi {
namespace {

static_assert(static_cast<int>(runtime::ReportedEffectState::stopped) == FEEL_STATE_STOPPED);
static_assert(static_cast<int>(runtime::ReportedEffectState::playing) == FEEL_STATE_PLAYING);
static_assert(static_cast<int>(runtime::ReportedEffectState::delayed) == FEEL_STATE_DELAYED);
static_assert(static_cast<int>(runtime::ReportedEffectState::emulated) == FEEL_STATE_EMULATED);
static_assert(static_cast<int>(PlayEnd::none) == FEEL_END_NONE);
static_assert(static_cast<int>(PlayEnd::stopped) == FEEL_END_STOPPED);
static_assert(static_cast<int>(PlayEnd::finished) == FEEL_END_FINISHED);
static_assert(static_cast<int>(DynamicReport::Kind::interim) == FEEL_REPORT_INTERIM);
static_assert(static_cast<int>(DynamicReport::Kind::final) == FEEL_REPORT_FINAL);

// A C callback as a host::DynamicCallback. Runs on the device's I/O thread.
host::DynamicCallback c_callback(feel_dynamic_callback callback, void* user_data) {
    return [callback, user_data](const host::DynamicEvent& e) {
        feel_dynamic_event out{};
        out.kind = static_cast<int32_t>(e.kind);
        out.t_us = e.t_us;
        out.axis_count = e.axis_count;
        for (int i = 0; i < kMaxAxes; ++i) {
            out.position[i] = e.position[i];
            out.velocity[i] = e.velocity[i];
            out.handle_velocity[i] = e.handle_velocity[i];
        }
        callback(&out, user_data);
    };
}

}  // namespace
}  // namespace feel::capi

using namespace feel::capi;

extern "C" {

// --- effects ------------------------------------------------------------------------------

void feel_effect_destroy(feel_effect* effect) {
    (void)guard("feel_effect_destroy", [&] {
        if (!effect) return succeed();
        // Unloading a stale effect (its device closed) is not an error here: it is gone.
        (void)effect->effect.unload();
        delete effect;
        return succeed();
    });
}

int feel_effect_start(feel_effect* effect, int32_t iterations, bool solo) {
    return guard("feel_effect_start", [&] {
        if (!effect) return null_argument("feel_effect_start", "effect");
        return from_status(effect->effect.start(iterations, solo));
    });
}

int feel_effect_stop(feel_effect* effect) {
    return guard("feel_effect_stop", [&] {
        if (!effect) return null_argument("feel_effect_stop", "effect");
        return from_status(effect->effect.stop());
    });
}

int feel_effect_status(feel_effect* effect, feel_effect_status_info* out) {
    return guard("feel_effect_status", [&] {
        if (!effect) return null_argument("feel_effect_status", "effect");
        if (!out) return null_argument("feel_effect_status", "out");
        feel::host::Result<feel::host::EffectStatusInfo> s = effect->effect.status();
        if (!s) return fail(s.status());
        const feel::host::EffectStatusInfo& info = s.value();
        *out = feel_effect_status_info{};
        out->state = static_cast<int32_t>(info.state);
        out->emulated = info.emulated;
        out->iterations = info.iterations;
        out->completed_iterations = info.completed_iterations;
        out->elapsed_us = info.elapsed_us;
        out->last_end = static_cast<int32_t>(info.last_end);
        return succeed();
    });
}

// --- dynamic reports ----------------------------------------------------------------------

feel_subscription* feel_effect_subscribe(feel_effect* effect, feel_dynamic_callback callback, void* user_data) {
    return guard_ptr<feel_subscription>("feel_effect_subscribe", [&]() -> feel_subscription* {
        if (!effect) return no_handle(null_argument("feel_effect_subscribe", "effect"));
        if (!callback) return no_handle(null_argument("feel_effect_subscribe", "callback"));
        if (!effect->effect.valid()) {
            fail(FEEL_ERROR_INVALID_HANDLE, "feel_effect_subscribe: the effect is no longer on a device");
            return nullptr;
        }
        return new feel_subscription{effect->effect.subscribe(c_callback(callback, user_data))};
    });
}

feel_subscription* feel_device_subscribe(feel_device* device, feel_dynamic_callback callback, void* user_data) {
    return guard_ptr<feel_subscription>("feel_device_subscribe", [&]() -> feel_subscription* {
        if (!device) return no_handle(null_argument("feel_device_subscribe", "device"));
        if (!callback) return no_handle(null_argument("feel_device_subscribe", "callback"));
        return new feel_subscription{device->device.subscribe(c_callback(callback, user_data))};
    });
}

void feel_unsubscribe(feel_subscription* subscription) {
    (void)guard("feel_unsubscribe", [&] {
        if (subscription) {
            subscription->subscription.reset();  // waits for a callback in progress
            delete subscription;
        }
        return succeed();
    });
}

// --- §9.5 ----------------------------------------------------------------------------------

feel_library* feel_library_load(const char* path, const char* address) {
    return guard_ptr<feel_library>("feel_library_load", [&]() -> feel_library* {
        if (!path) return no_handle(null_argument("feel_library_load", "path"));
        const std::string_view where = address && *address ? address : "sim:iforce2";
        feel::host::Result<feel::host::SensationLibrary> library =
            feel::host::SensationLibrary::load(std::filesystem::path(path), where);
        if (!library) {
            fail(library.status());
            return nullptr;
        }
        auto out = std::unique_ptr<feel_library>(new feel_library{std::move(library).value(), nullptr});
        out->device.reset(new feel_device{out->library.device(), true});
        return out.release();
    });
}

int feel_library_play(feel_library* library, const char* name) {
    return guard("feel_library_play", [&] {
        if (!library) return null_argument("feel_library_play", "library");
        if (!name) return null_argument("feel_library_play", "name");
        return from_status(library->library.play(name));
    });
}

int feel_library_stop(feel_library* library, const char* name) {
    return guard("feel_library_stop", [&] {
        if (!library) return null_argument("feel_library_stop", "library");
        if (!name) return null_argument("feel_library_stop", "name");
        return from_status(library->library.stop(name));
    });
}

feel_device* feel_library_device(feel_library* library) {
    return guard_ptr<feel_device>("feel_library_device", [&]() -> feel_device* {
        if (!library) return no_handle(null_argument("feel_library_device", "library"));
        return library->device.get();
    });
}

void feel_library_free(feel_library* library) {
    (void)guard("feel_library_free", [&] {
        if (!library) return succeed();
        library->device.reset();
        feel::host::Device device = library->library.device();
        delete library;   // frees the library's effects
        device.close();   // and closes the device it opened
        return succeed();
    });
}

}  // extern "C"
