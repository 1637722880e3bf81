// SCHED_FIFO for the threads on a report's way (thread_priority.hpp).
#include "feel/transport/thread_priority.hpp"

#include <pthread.h>
#include <sched.h>

#include <cstring>

namespace feel::transport {

std::string check_fifo_priority(const char* field, int32_t priority) {
    if (priority == 0 || (priority >= kMinFifoPriority && priority <= kMaxFifoPriority)) return {};
    return std::string(field) + " = " + std::to_string(priority) + " is out of range (allowed " +
           std::to_string(kMinFifoPriority) + ".." + std::to_string(kMaxFifoPriority) +
           ", a SCHED_FIFO priority; or 0 for an ordinary thread)";
}

ThreadPriority raise_thread_priority(int32_t priority) {
    ThreadPriority out;
    if (priority == 0) {
        out.note = "SCHED_OTHER (SCHED_FIFO not asked for)";
        return out;
    }
    if (std::string wrong = check_fifo_priority("priority", priority); !wrong.empty()) {
        out.note = "SCHED_OTHER (" + wrong + ")";
        return out;
    }
    sched_param param{};
    param.sched_priority = priority;
    if (const int error = pthread_setschedparam(pthread_self(), SCHED_FIFO, &param); error != 0) {
        out.note = "SCHED_OTHER (SCHED_FIFO refused: " + std::string(std::strerror(error)) + ")";
        return out;
    }
    out.fifo = true;
    out.priority = priority;
    out.note = "SCHED_FIFO priority " + std::to_string(priority);
    return out;
}

}  // namespace feel::transport
