#include "io/temporary_files.hpp"

#include "io/atomic_output.hpp"

#include <atomic>
#include <climits>
#include <cstring>

#include <pthread.h>
#include <unistd.h>

namespace obbsat::io {

namespace {

// A handful of temporaries exist at once (obbsat gen: a directory and its five
// files; obbsat accuracy: two files); the table has room to spare.
constexpr int slot_count = 32;

// A slot's state: free, claimed (its path being written), or a live file or
// directory the handler removes. The handler reads the path only in the last
// two states, which are published after the path is complete.
enum slot_state : int { slot_free = 0, slot_claimed, slot_file, slot_directory };

struct slot {
    std::atomic<int> state{slot_free};
    char path[PATH_MAX];
};

// Lock-free atomics are safe to read in a signal handler; plain globals are
// what it may touch besides.
static_assert(std::atomic<int>::is_always_lock_free);
slot slots[slot_count];

constexpr int handled_signals[] = {SIGINT, SIGTERM, SIGHUP, SIGPIPE};

// Only async-signal-safe calls: unlink, rmdir, raise. Files go first, so that
// a directory is empty when its turn comes.
extern "C" void remove_temporaries_and_end(int signal_number) {
    for (slot& s : slots) {
        if (s.state.load(std::memory_order_acquire) == slot_file) {
            ::unlink(s.path);
        }
    }
    for (slot& s : slots) {
        if (s.state.load(std::memory_order_acquire) == slot_directory) {
            ::rmdir(s.path);
        }
    }
    // SA_RESETHAND restored the default action on entry; the signal raised
    // again is held until this handler returns, then ends the program by it,
    // so the caller (a shell, a test) sees how the program ended.
    ::raise(signal_number);
}

}  // namespace

void remove_temporaries_on_signal() {
    for (const int signal_number : handled_signals) {
        struct sigaction current {};
        if (::sigaction(signal_number, nullptr, &current) != 0 || current.sa_handler == SIG_IGN) {
            continue;  // an ignored signal (nohup, a background job) stays ignored
        }
        struct sigaction handler {};
        handler.sa_handler = remove_temporaries_and_end;
        sigemptyset(&handler.sa_mask);
        for (const int other : handled_signals) {
            sigaddset(&handler.sa_mask, other);  // one removal at a time
        }
        handler.sa_flags = static_cast<int>(SA_RESETHAND);
        ::sigaction(signal_number, &handler, nullptr);
    }
}

temporary_registration::temporary_registration(const std::string& path, kind what) {
    if (path.size() >= PATH_MAX) {
        throw output_error(path.substr(0, 64) + "...: path longer than PATH_MAX");
    }
    for (int i = 0; i < slot_count; ++i) {
        int expected = slot_free;
        if (slots[i].state.compare_exchange_strong(expected, slot_claimed, std::memory_order_acq_rel)) {
            std::memcpy(slots[i].path, path.c_str(), path.size() + 1);
            slots[i].state.store(what == kind::file ? slot_file : slot_directory, std::memory_order_release);
            slot_ = i;
            return;
        }
    }
    throw output_error(path + ": more than " + std::to_string(slot_count) + " temporary files at once");
}

temporary_registration::temporary_registration(temporary_registration&& other) noexcept
    : slot_(other.slot_) {
    other.slot_ = -1;
}

temporary_registration& temporary_registration::operator=(temporary_registration&& other) noexcept {
    if (this != &other) {
        release();
        slot_ = other.slot_;
        other.slot_ = -1;
    }
    return *this;
}

void temporary_registration::release() noexcept {
    if (slot_ >= 0) {
        slots[slot_].state.store(slot_free, std::memory_order_release);
        slot_ = -1;
    }
}

std::string temporary_pattern(const std::string& directory, const char* tag) {
    return directory + ".obbsat-" + tag + ".XXXXXX";
}

signals_held::signals_held() {
    sigset_t held;
    sigemptyset(&held);
    for (const int signal_number : handled_signals) {
        sigaddset(&held, signal_number);
    }
    ::pthread_sigmask(SIG_BLOCK, &held, &saved_);
}

signals_held::~signals_held() { ::pthread_sigmask(SIG_SETMASK, &saved_, nullptr); }

}  // namespace obbsat::io
