// feel.h: effects (start, stop, status, destroy), dynamic report subscriptions, and the
// two calls of §9.5 (feel_library_load, feel_library_play).
#include <algorithm>
#include <filesystem>
#include <string>
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
        out.size = sizeof out;
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

feel_library* wrap_library(host::SensationLibrary library, bool owns_device) {
    auto out = std::unique_ptr<feel_library>(new feel_library{std::move(library), nullptr, owns_device, {}, {}});
    out->device.reset(new feel_device{out->library.device(), true});  // lent: feel_close refuses it
    out->names = out->library.names();
    return out.release();
}

// The views of a sensation's effects, made on first use; nullptr (error recorded) for a
// name the library lacks.
std::vector<std::unique_ptr<feel_effect>>* effect_views(const char* function, feel_library* library,
                                                        const char* name) {
    if (auto it = library->effect_views.find(std::string_view(name)); it != library->effect_views.end()) {
        return &it->second;
    }
    if (std::find(library->names.begin(), library->names.end(), name) == library->names.end()) {
        std::string known;
        for (const std::string& n : library->names) known += (known.empty() ? "" : ", ") + n;
        fail(FEEL_ERROR_INVALID_PARAMETER,
             std::string(function) + ": no sensation \"" + name + "\" in the library (it has: " + known + ")");
        return nullptr;
    }
    std::vector<std::unique_ptr<feel_effect>> views;
    for (feel::host::Effect& e : library->library.effects(name)) views.push_back(std::make_unique<feel_effect>(&e));
    return &library->effect_views.emplace(name, std::move(views)).first->second;
}

}  // namespace
}  // namespace feel::capi

using namespace feel::capi;

extern "C" {

// --- effects ------------------------------------------------------------------------------

void feel_effect_destroy(feel_effect* effect) {
    (void)guard("feel_effect_destroy", [&] {
        if (!effect) return succeed();
        if (effect->borrowed) {
            return fail(FEEL_ERROR_INVALID_PARAMETER,
                        "feel_effect_destroy: this effect belongs to a library; feel_library_free frees it");
        }
        // Unloading a stale effect (its device closed) is not an error here: it is gone.
        (void)effect->effect->unload();
        delete effect;
        return succeed();
    });
}

int feel_effect_start(feel_effect* effect, int32_t iterations, bool solo) {
    return guard("feel_effect_start", [&] {
        if (!effect) return null_argument("feel_effect_start", "effect");
        return from_status(effect->effect->start(iterations, solo));
    });
}

int feel_effect_stop(feel_effect* effect) {
    return guard("feel_effect_stop", [&] {
        if (!effect) return null_argument("feel_effect_stop", "effect");
        return from_status(effect->effect->stop());
    });
}

int feel_effect_status(feel_effect* effect, feel_effect_status_info* out) {
    return guard("feel_effect_status", [&] {
        if (!effect) return null_argument("feel_effect_status", "effect");
        if (const int rc = check_out("feel_effect_status", "out", out); rc != FEEL_OK) return rc;
        feel::host::Result<feel::host::EffectStatusInfo> s = effect->effect->status();
        if (!s) return fail(s.status());
        const feel::host::EffectStatusInfo& info = s.value();
        feel_effect_status_info status{};
        status.state = static_cast<int32_t>(info.state);
        status.emulated = info.emulated;
        status.iterations = info.iterations;
        status.completed_iterations = info.completed_iterations;
        status.elapsed_us = info.elapsed_us;
        status.last_end = static_cast<int32_t>(info.last_end);
        write_out(status, out);
        return succeed();
    });
}

// --- dynamic reports ----------------------------------------------------------------------

feel_subscription* feel_effect_subscribe(feel_effect* effect, feel_dynamic_callback callback, void* user_data) {
    return guard_ptr<feel_subscription>("feel_effect_subscribe", [&]() -> feel_subscription* {
        if (!effect) return no_handle(null_argument("feel_effect_subscribe", "effect"));
        if (!callback) return no_handle(null_argument("feel_effect_subscribe", "callback"));
        if (!effect->effect->valid()) {
            fail(FEEL_ERROR_INVALID_HANDLE, "feel_effect_subscribe: the effect is no longer on a device");
            return nullptr;
        }
        return new feel_subscription{effect->effect->subscribe(c_callback(callback, user_data))};
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
        return wrap_library(std::move(library).value(), true);
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
        const bool close = library->owns_device;
        delete library;             // frees the library's effects
        if (close) device.close();  // and closes the device it opened
        return succeed();
    });
}

feel_library* feel_library_load_on(const char* path, feel_device* device, const char* const* names,
                                   int32_t count) {
    return guard_ptr<feel_library>("feel_library_load_on", [&]() -> feel_library* {
        if (!path) return no_handle(null_argument("feel_library_load_on", "path"));
        if (!device) return no_handle(null_argument("feel_library_load_on", "device"));
        if (count < 0 || count > 4096) return no_handle(out_of_range("feel_library_load_on", "count", count, 0, 4096));
        if (count > 0 && !names) return no_handle(null_argument("feel_library_load_on", "names"));
        std::vector<std::string> only;
        for (int32_t i = 0; i < count; ++i) {
            if (!names[i]) return no_handle(null_argument("feel_library_load_on", "names[i]"));
            only.emplace_back(names[i]);
        }
        feel::host::Result<feel::host::SensationLibrary> library =
            only.empty() ? feel::host::SensationLibrary::load(std::filesystem::path(path), device->device)
                         : feel::host::SensationLibrary::load(std::filesystem::path(path), device->device, only);
        if (!library) return no_handle(fail(library.status()));
        return wrap_library(std::move(library).value(), false);
    });
}

int feel_library_play_ex(feel_library* library, const char* name, int32_t iterations) {
    return guard("feel_library_play_ex", [&] {
        if (!library) return null_argument("feel_library_play_ex", "library");
        if (!name) return null_argument("feel_library_play_ex", "name");
        return from_status(library->library.play(name, iterations));
    });
}

int feel_library_stop_all(feel_library* library) {
    return guard("feel_library_stop_all", [&] {
        if (!library) return null_argument("feel_library_stop_all", "library");
        return from_status(library->library.stop_all());
    });
}

int32_t feel_library_sensation_count(const feel_library* library) {
    int32_t count = 0;
    (void)guard("feel_library_sensation_count", [&] {
        if (!library) return null_argument("feel_library_sensation_count", "library");
        count = static_cast<int32_t>(library->names.size());
        return succeed();
    });
    return count;
}

const char* feel_library_sensation_name(const feel_library* library, int32_t index) {
    const char* name = nullptr;
    (void)guard("feel_library_sensation_name", [&] {
        if (!library) return null_argument("feel_library_sensation_name", "library");
        const auto count = static_cast<int32_t>(library->names.size());
        if (index < 0 || index >= count) {
            return out_of_range("feel_library_sensation_name", "index", index, 0, count - 1);
        }
        name = library->names[static_cast<std::size_t>(index)].c_str();
        return succeed();
    });
    return name;
}

int32_t feel_library_effect_count(feel_library* library, const char* name) {
    int32_t count = 0;
    (void)guard("feel_library_effect_count", [&] {
        if (!library) return null_argument("feel_library_effect_count", "library");
        if (!name) return null_argument("feel_library_effect_count", "name");
        const auto* views = effect_views("feel_library_effect_count", library, name);
        if (!views) return feel_last_error();
        count = static_cast<int32_t>(views->size());
        return succeed();
    });
    return count;
}

feel_effect* feel_library_effect(feel_library* library, const char* name, int32_t index) {
    return guard_ptr<feel_effect>("feel_library_effect", [&]() -> feel_effect* {
        if (!library) return no_handle(null_argument("feel_library_effect", "library"));
        if (!name) return no_handle(null_argument("feel_library_effect", "name"));
        auto* views = effect_views("feel_library_effect", library, name);
        if (!views) return nullptr;
        const auto count = static_cast<int32_t>(views->size());
        if (index < 0 || index >= count) {
            return no_handle(out_of_range("feel_library_effect", "index", index, 0, count - 1));
        }
        return (*views)[static_cast<std::size_t>(index)].get();
    });
}

}  // extern "C"
