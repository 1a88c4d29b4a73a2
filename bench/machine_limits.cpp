// obbsat_machine_limits: what this machine can do at best, measured, as the
// ceilings of the roofline the benchmark rates are compared against:
//   - float throughput of FMA, mul+add and add+max chains (AVX-512, AVX2);
//   - read bandwidth of a streaming sum per working-set size;
//   - throughput of independent random reads of 32-byte records;
//   - the rate at which fresh memory can be put to use: mapped, each page
//     written once (the OS finds and clears it), unmapped.
// Each figure is the median of several timed trials after a calibration run,
// on 1 and on 2 threads (2-thread figures are aggregates over both).
//
// Usage: obbsat_machine_limits [--json FILE] [--trials N] [--trial-seconds S]
#include "machine_kernels.hpp"

#include <obbsat/backend.hpp>
#include <obbsat/scene.hpp>

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iostream>
#include <memory>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include <sys/mman.h>

namespace {

using obbsat_bench::machine::kernel_set;

struct settings {
    unsigned trials = 5;
    double trial_seconds = 0.05;
    std::string json_path;
};

struct measurement {
    std::string section;  ///< "float", "read", "random_records" or "fresh_memory"
    std::string isa;
    std::string what;     ///< operation, working set or record count, as text
    double size = 0.0;    ///< working-set bytes or record count; 0 for float
    unsigned threads = 0;
    double rate = 0.0;    ///< lane-ops/s, bytes/s or records/s (aggregate)
};

struct aligned_free {
    void operator()(void* p) const { std::free(p); }
};

template <class T>
std::unique_ptr<T[], aligned_free> aligned_array(std::size_t count) {
    const std::size_t bytes = (count * sizeof(T) + 63) / 64 * 64;
    void* p = std::aligned_alloc(64, bytes == 0 ? 64 : bytes);
    if (p == nullptr) {
        throw std::bad_alloc();
    }
    return std::unique_ptr<T[], aligned_free>(static_cast<T*>(p));
}

/// Runs body(thread, amount) on `threads` threads released together; returns
/// the seconds from the first thread starting its body to the last one
/// finishing it (thread start-up and join are not counted).
template <class Body>
double timed_parallel(unsigned threads, std::size_t amount, const Body& body) {
    using clock = std::chrono::steady_clock;
    std::atomic<unsigned> ready{0};
    std::atomic<bool> go{false};
    std::vector<clock::time_point> starts(threads), ends(threads);
    std::vector<std::thread> workers;
    for (unsigned t = 0; t < threads; ++t) {
        workers.emplace_back([&, t] {
            ready.fetch_add(1);
            while (!go.load(std::memory_order_acquire)) {
                std::this_thread::yield();
            }
            starts[t] = clock::now();
            body(t, amount);
            ends[t] = clock::now();
        });
    }
    while (ready.load() != threads) {
        std::this_thread::yield();
    }
    go.store(true, std::memory_order_release);
    for (auto& w : workers) {
        w.join();
    }
    const auto first = *std::min_element(starts.begin(), starts.end());
    const auto last = *std::max_element(ends.begin(), ends.end());
    return std::chrono::duration<double>(last - first).count();
}

/// Units per second over all threads, where body(thread, amount) does
/// `amount * units_per_amount` units on each thread: the median of
/// `trials` runs sized to about trial_seconds each.
template <class Body>
double median_rate(const settings& s, unsigned threads, double units_per_amount, const Body& body) {
    std::size_t amount = 1;
    double seconds = timed_parallel(threads, amount, body);
    while (seconds < s.trial_seconds / 8) {
        amount *= 2;
        seconds = timed_parallel(threads, amount, body);
    }
    amount = std::max<std::size_t>(
        1, static_cast<std::size_t>(static_cast<double>(amount) * s.trial_seconds / seconds));
    std::vector<double> rates;
    for (unsigned i = 0; i < s.trials; ++i) {
        const double t = timed_parallel(threads, amount, body);
        rates.push_back(static_cast<double>(amount) * units_per_amount * threads / t);
    }
    std::sort(rates.begin(), rates.end());
    return rates[rates.size() / 2];
}

using arithmetic_fn = void (*)(float*, std::size_t, float, float);

double arithmetic_rate(const settings& s, const kernel_set& k, arithmetic_fn fn, unsigned threads) {
    const std::size_t floats = obbsat_bench::machine::arithmetic_chains * k.lanes;
    std::vector<std::unique_ptr<float[], aligned_free>> states;
    for (unsigned t = 0; t < threads; ++t) {
        states.push_back(aligned_array<float>(floats));
        std::fill(states.back().get(), states.back().get() + floats, 1.0f);
    }
    // m = 1 and c = 0 keep every chain at 1.0: no overflow, no subnormals,
    // and the kernel (in another translation unit) cannot know it.
    return median_rate(s, threads, static_cast<double>(floats), [&](unsigned t, std::size_t rounds) {
        fn(states[t].get(), rounds, 1.0f, 0.0f);
    });
}

double read_rate(const settings& s, const kernel_set& k, std::size_t bytes, unsigned threads) {
    const std::size_t count = bytes / sizeof(float) / k.read_block * k.read_block;
    std::vector<std::unique_ptr<float[], aligned_free>> buffers;
    for (unsigned t = 0; t < threads; ++t) {
        buffers.push_back(aligned_array<float>(count));
        std::fill(buffers.back().get(), buffers.back().get() + count, 1.0f);
    }
    std::atomic<float> sink{0.0f};
    const double rate = median_rate(s, threads, static_cast<double>(count * sizeof(float)),
                                    [&](unsigned t, std::size_t passes) {
                                        sink.store(k.read_sum(buffers[t].get(), count, passes));
                                    });
    return rate;
}

double random_record_rate(const settings& s, const kernel_set& k, std::size_t records,
                          unsigned threads) {
    constexpr std::size_t floats_per_record = obbsat_bench::machine::record_floats;
    // 4M indices per thread: a pass takes long enough to time, and the index
    // stream (4 bytes per 32-byte record) stays a small share of the traffic.
    constexpr std::size_t indices_per_thread = std::size_t{1} << 22;
    auto table = aligned_array<float>(records * floats_per_record);
    std::fill(table.get(), table.get() + records * floats_per_record, 1.0f);
    std::vector<std::vector<std::uint32_t>> indices(threads);
    for (unsigned t = 0; t < threads; ++t) {
        obbsat::seeded_random random(1000 + t);
        indices[t].resize(indices_per_thread);
        for (auto& i : indices[t]) {
            i = static_cast<std::uint32_t>(random.below(records));
        }
    }
    std::atomic<float> sink{0.0f};
    return median_rate(s, threads, static_cast<double>(indices_per_thread),
                       [&](unsigned t, std::size_t passes) {
                           float total = 0.0f;
                           for (std::size_t p = 0; p < passes; ++p) {
                               total += k.sum_records(table.get(), indices[t].data(),
                                                      indices[t].size());
                           }
                           sink.store(total);
                       });
}

/// Bytes per second over all threads of fresh memory put to use: each
/// thread maps `bytes`, writes one byte in each 4 KiB page, and unmaps them,
/// over and over. `huge` asks for transparent huge pages on the block
/// (2 MiB-aligned by mapping 2 MiB more and using the aligned part).
double fresh_memory_rate(const settings& s, std::size_t bytes, bool huge, unsigned threads) {
    constexpr std::size_t page = 4096;
    constexpr std::size_t huge_page = std::size_t{2} << 20;
    std::atomic<bool> failed{false};
    const double rate = median_rate(s, threads, static_cast<double>(bytes), [&](unsigned, std::size_t blocks) {
        for (std::size_t b = 0; b < blocks; ++b) {
            const std::size_t mapped = bytes + huge_page;
            void* block = mmap(nullptr, mapped, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
            if (block == MAP_FAILED) {
                failed.store(true);
                return;
            }
            const auto address = reinterpret_cast<std::uintptr_t>(block);
            auto* first = reinterpret_cast<volatile char*>((address + huge_page - 1) / huge_page * huge_page);
            if (huge) {
                (void)madvise(const_cast<char*>(first), bytes, MADV_HUGEPAGE);
            }
            for (std::size_t at = 0; at < bytes; at += page) {
                first[at] = 1;
            }
            munmap(block, mapped);
        }
    });
    if (failed.load()) {
        throw std::runtime_error("cannot map " + std::to_string(bytes) + " bytes");
    }
    return rate;
}

std::string cpu_model() {
    std::ifstream cpuinfo("/proc/cpuinfo");
    std::string line;
    while (std::getline(cpuinfo, line)) {
        if (line.rfind("model name", 0) == 0) {
            const auto colon = line.find(':');
            if (colon != std::string::npos) {
                return line.substr(line.find_first_not_of(' ', colon + 1));
            }
        }
    }
    return "unknown";
}

std::string size_text(std::size_t bytes) {
    if (bytes >= (std::size_t{1} << 20)) {
        return std::to_string(bytes >> 20) + " MiB";
    }
    return std::to_string(bytes >> 10) + " KiB";
}

std::string json_escape(const std::string& text) {
    std::string out;
    for (const char ch : text) {
        if (ch == '"' || ch == '\\') {
            out += '\\';
        }
        if (static_cast<unsigned char>(ch) >= 0x20) {
            out += ch;
        }
    }
    return out;
}

std::string to_json(const std::vector<measurement>& rows, const std::string& model) {
    std::ostringstream out;
    out.precision(6);
    out << "{\n  \"cpu_model\": \"" << json_escape(model) << "\",\n"
        << "  \"hardware_threads\": " << std::thread::hardware_concurrency() << ",\n"
        << "  \"measurements\": [\n";
    for (std::size_t i = 0; i < rows.size(); ++i) {
        const measurement& m = rows[i];
        out << "    {\"section\": \"" << m.section << "\", \"isa\": \"" << m.isa
            << "\", \"what\": \"" << json_escape(m.what) << "\", \"size\": " << m.size
            << ", \"threads\": " << m.threads << ", \"rate\": " << m.rate << "}"
            << (i + 1 < rows.size() ? ",\n" : "\n");
    }
    out << "  ]\n}\n";
    return out.str();
}

/// Writes `text` to `path` through a temporary file, so a failed run leaves
/// no half-written file behind.
bool write_whole_file(const std::string& path, const std::string& text) {
    const std::string temporary = path + ".tmp";
    {
        std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
        out << text;
        out.flush();
        if (!out) {
            std::remove(temporary.c_str());
            return false;
        }
    }
    if (std::rename(temporary.c_str(), path.c_str()) != 0) {
        std::remove(temporary.c_str());
        return false;
    }
    return true;
}

std::optional<settings> parse_arguments(int argc, char** argv) {
    settings s;
    for (int i = 1; i < argc; ++i) {
        const std::string arg = argv[i];
        const bool has_value = i + 1 < argc;
        try {
            if (arg == "--json" && has_value) {
                s.json_path = argv[++i];
            } else if (arg == "--trials" && has_value) {
                const int n = std::stoi(argv[++i]);
                if (n < 1 || n > 1000) {
                    throw std::out_of_range("trials");
                }
                s.trials = static_cast<unsigned>(n);
            } else if (arg == "--trial-seconds" && has_value) {
                s.trial_seconds = std::stod(argv[++i]);
                if (!(s.trial_seconds > 0.0 && s.trial_seconds <= 60.0)) {
                    throw std::out_of_range("trial-seconds");
                }
            } else {
                std::cerr << "obbsat_machine_limits: unknown or incomplete argument '" << arg
                          << "'\nusage: obbsat_machine_limits [--json FILE] [--trials N in 1..1000]"
                             " [--trial-seconds S in (0, 60]]\n";
                return std::nullopt;
            }
        } catch (const std::exception&) {
            std::cerr << "obbsat_machine_limits: bad value '" << argv[i] << "' for " << arg << "\n";
            return std::nullopt;
        }
    }
    return s;
}

}  // namespace

int main(int argc, char** argv) {
    const std::optional<settings> parsed = parse_arguments(argc, argv);
    if (!parsed) {
        return 2;
    }
    const settings& s = *parsed;
    namespace m = obbsat_bench::machine;

    // Only sets this CPU runs; the kernels of the others are never called.
    std::vector<kernel_set> sets;
    if (obbsat::cpu_supports(obbsat::backend::avx512)) {
        sets.push_back(m::avx512_kernels());
    } else {
        std::cout << "skipping avx512: this CPU (or build) does not run it\n";
    }
    if (obbsat::cpu_supports(obbsat::backend::avx2) && __builtin_cpu_supports("fma")) {
        sets.push_back(m::avx2_kernels());
    } else {
        std::cout << "skipping avx2: this CPU (or build) does not run AVX2 with FMA\n";
    }
    sets.push_back(m::sse2_kernels());
    const kernel_set& widest = sets.front();
    const unsigned thread_counts[] = {1, 2};
    const std::string model = cpu_model();
    std::vector<measurement> rows;

    std::printf("obbsat_machine_limits on %s (%u hardware threads), median of %u trials of ~%.2f s\n\n",
                model.c_str(), std::thread::hardware_concurrency(), s.trials, s.trial_seconds);

    std::printf("Float throughput, G lane-ops/s (an FMA lane-op is 2 flops)\n");
    std::printf("%-8s %-8s %10s %10s\n", "isa", "op", "1 thread", "2 threads");
    for (const kernel_set& k : sets) {
        if (k.fma == nullptr) {
            continue;  // the baseline set is there for the memory tests only
        }
        const std::pair<const char*, arithmetic_fn> ops[] = {
            {"fma", k.fma}, {"mul+add", k.mul_add}, {"add+max", k.add_max}};
        for (const auto& [op, fn] : ops) {
            std::printf("%-8s %-8s", k.isa, op);
            for (const unsigned threads : thread_counts) {
                const double rate = arithmetic_rate(s, k, fn, threads);
                rows.push_back({"float", k.isa, op, 0.0, threads, rate});
                std::printf(" %10.1f", rate / 1e9);
                std::fflush(stdout);
            }
            std::printf("\n");
        }
    }

    std::printf("\nStreaming read (%s loads), GB/s, working set per thread\n", widest.isa);
    std::printf("%-10s %10s %10s\n", "set", "1 thread", "2 threads");
    const std::size_t working_sets[] = {std::size_t{16} << 10, std::size_t{256} << 10,
                                        std::size_t{8} << 20, std::size_t{256} << 20};
    for (const std::size_t bytes : working_sets) {
        std::printf("%-10s", size_text(bytes).c_str());
        for (const unsigned threads : thread_counts) {
            const double rate = read_rate(s, widest, bytes, threads);
            rows.push_back({"read", widest.isa, size_text(bytes), static_cast<double>(bytes),
                            threads, rate});
            std::printf(" %10.1f", rate / 1e9);
            std::fflush(stdout);
        }
        std::printf("\n");
    }

    std::printf("\nRandom 32-byte records, many loads in flight, ns per record (aggregate)\n");
    std::printf("%-10s %10s %10s\n", "records", "1 thread", "2 threads");
    const std::size_t record_counts[] = {4096, std::size_t{1} << 20, std::size_t{2} << 20};
    for (const std::size_t records : record_counts) {
        std::printf("%-10zu", records);
        for (const unsigned threads : thread_counts) {
            const double rate = random_record_rate(s, widest, records, threads);
            rows.push_back({"random_records", widest.isa, std::to_string(records),
                            static_cast<double>(records), threads, rate});
            std::printf(" %10.2f", 1e9 / rate);
            std::fflush(stdout);
        }
        std::printf("\n");
    }

    std::printf("\nFresh memory (mapped, one write per 4 KiB page, unmapped), GB/s (aggregate), 64 MiB per thread\n");
    std::printf("%-22s %10s %10s\n", "pages", "1 thread", "2 threads");
    for (const bool huge : {false, true}) {
        const char* what = huge ? "huge pages advised" : "4 KiB pages";
        std::printf("%-22s", what);
        for (const unsigned threads : thread_counts) {
            const std::size_t bytes = std::size_t{64} << 20;
            double rate = 0.0;
            try {
                rate = fresh_memory_rate(s, bytes, huge, threads);
            } catch (const std::exception& e) {
                std::cerr << "\nobbsat_machine_limits: " << e.what() << "\n";
                return 1;
            }
            rows.push_back({"fresh_memory", "", what, static_cast<double>(bytes), threads, rate});
            std::printf(" %10.2f", rate / 1e9);
            std::fflush(stdout);
        }
        std::printf("\n");
    }

    if (!s.json_path.empty()) {
        if (!write_whole_file(s.json_path, to_json(rows, model))) {
            std::cerr << "obbsat_machine_limits: cannot write " << s.json_path << ": "
                      << std::strerror(errno) << "\n";
            return 1;
        }
        std::printf("\nwrote %s\n", s.json_path.c_str());
    }
    return 0;
}
