// The device runtime: a RuntimePipeline ticked by a RealtimeLoop thread.
//
// The pipeline is built on the host thread, before the loop exists, so every allocation
// happens there; the loop's callback only calls RuntimePipeline::tick. The loop numbers its
// ticks from 0 at every start; the pipeline's index continues from where the last run
// stopped (base + tick), so device time never goes back and never shows the wall-clock
// gap between a stop and a start.
#include "feel/runtime/device_runtime.hpp"

#include <utility>

namespace feel::runtime {

DeviceRuntime::DeviceRuntime(const RuntimeConfig& config, std::unique_ptr<RuntimeBackend> backend,
                             const DeviceRuntimeOptions& options)
    : DeviceRuntime(std::make_unique<RuntimePipeline>(config, std::move(backend)), options) {}

// HostLink takes the queues' addresses before pipeline_ takes ownership: the pipeline
// object itself does not move, so they stay valid.
DeviceRuntime::DeviceRuntime(std::unique_ptr<RuntimePipeline> pipeline, const DeviceRuntimeOptions& options)
    : HostLink(pipeline->commands(), pipeline->reports()), pipeline_(std::move(pipeline)), options_(options) {}

DeviceRuntime::~DeviceRuntime() {
    // The loop must be gone before the pipeline it ticks; an exception cannot come out of
    // the callback (tick is noexcept), so stop() cannot throw here.
    loop_.stop();
}

void DeviceRuntime::start() {
    RealtimeLoopOptions loop_options;
    loop_options.rate_hz = pipeline_->config().loop_rate_hz;
    loop_options.realtime_priority = options_.realtime_priority;
    loop_options.fifo_priority = options_.fifo_priority;
    loop_options.lock_memory = options_.lock_memory;
    RuntimePipeline* pipeline = pipeline_.get();
    const int64_t base = pipeline->next_tick_index();
    ReportSignal* signal = options_.report_signal;
    loop_.start(loop_options, [pipeline, base, signal](int64_t tick, int64_t /*t_us*/) {
        pipeline->tick(base + tick);
        if (signal != nullptr && pipeline->reports().size_approx() != 0) signal->reports_ready();
    });
}

void DeviceRuntime::stop() { loop_.stop(); }

DeviceRuntimeStats DeviceRuntime::stats() const noexcept {
    DeviceRuntimeStats s;
    s.pipeline = pipeline_->counters();
    s.loop = loop_.stats();
    return s;
}

}  // namespace feel::runtime
