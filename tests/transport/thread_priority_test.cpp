// raise_thread_priority and check_fifo_priority (feel/transport/thread_priority.hpp): what
// the kernel says the thread runs under is the truth the result is held to, whether or not
// this process may use SCHED_FIFO.
#include "feel/transport/thread_priority.hpp"

#include <gtest/gtest.h>
#include <pthread.h>
#include <sched.h>

#include <thread>

namespace feel::transport {
namespace {

struct Policy {
    int policy = -1;
    int priority = -1;
};

Policy policy_of_this_thread() {
    Policy p;
    sched_param param{};
    pthread_getschedparam(pthread_self(), &p.policy, &param);
    p.priority = param.sched_priority;
    return p;
}

// Each case on its own thread, so the test runner's thread is never raised.
template <class F>
void on_a_new_thread(F f) {
    std::thread t(f);
    t.join();
}

TEST(ThreadPriority, ZeroLeavesTheThreadOrdinary) {
    on_a_new_thread([] {
        const Policy before = policy_of_this_thread();
        const ThreadPriority r = raise_thread_priority(0);
        EXPECT_FALSE(r.fifo);
        EXPECT_EQ(r.priority, 0);
        EXPECT_NE(r.note.find("not asked for"), std::string::npos) << r.note;
        const Policy after = policy_of_this_thread();
        EXPECT_EQ(after.policy, before.policy);
        EXPECT_EQ(after.priority, before.priority);
    });
}

TEST(ThreadPriority, AskedForTheThreadRunsWhatTheResultSays) {
    on_a_new_thread([] {
        const ThreadPriority r = raise_thread_priority(7);
        const Policy now = policy_of_this_thread();
        if (r.fifo) {
            EXPECT_EQ(now.policy, SCHED_FIFO);
            EXPECT_EQ(now.priority, 7);
            EXPECT_EQ(r.priority, 7);
            EXPECT_EQ(r.note, "SCHED_FIFO priority 7");
        } else {  // a process without the privilege: refused, said, and left ordinary
            EXPECT_EQ(now.policy, SCHED_OTHER);
            EXPECT_NE(r.note.find("SCHED_FIFO refused"), std::string::npos) << r.note;
        }
    });
}

TEST(ThreadPriority, OutOfRangeChangesNothingAndNamesTheRange) {
    for (const int32_t wrong : {-1, 100, 1000}) {
        on_a_new_thread([wrong] {
            const Policy before = policy_of_this_thread();
            const ThreadPriority r = raise_thread_priority(wrong);
            EXPECT_FALSE(r.fifo);
            EXPECT_NE(r.note.find("1..99"), std::string::npos) << r.note;
            EXPECT_EQ(policy_of_this_thread().policy, before.policy);
        });
    }
}

TEST(ThreadPriority, TheCheckNamesTheFieldTheValueAndTheRange) {
    EXPECT_EQ(check_fifo_priority("io_fifo_priority", 0), "");
    EXPECT_EQ(check_fifo_priority("io_fifo_priority", 1), "");
    EXPECT_EQ(check_fifo_priority("io_fifo_priority", 99), "");
    const std::string m = check_fifo_priority("io_fifo_priority", 100);
    EXPECT_NE(m.find("io_fifo_priority = 100"), std::string::npos) << m;
    EXPECT_NE(m.find("1..99"), std::string::npos) << m;
    EXPECT_NE(m.find("or 0"), std::string::npos) << m;
    EXPECT_NE(check_fifo_priority("service_fifo_priority", -3).find("service_fifo_priority = -3"), std::string::npos);
}

}  // namespace
}  // namespace feel::transport
