#include <obbsat/oracle/classify_pairs.hpp>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <thread>

namespace obbsat::oracle {

namespace {

bool is_finite(const rect& r) {
    return std::isfinite(r.ul.x) && std::isfinite(r.ul.y) && std::isfinite(r.ur.x) &&
           std::isfinite(r.ur.y) && std::isfinite(r.lr.x) && std::isfinite(r.lr.y) &&
           std::isfinite(r.ll.x) && std::isfinite(r.ll.y);
}

void check_inputs(const rect* rects, std::size_t rect_count, const pair_index* pairs,
                  std::size_t pair_count) {
    for (std::size_t i = 0; i < pair_count; ++i) {
        const std::uint32_t worst = std::max(pairs[i].a, pairs[i].b);
        if (worst >= rect_count) {
            throw std::out_of_range("obbsat::oracle::classify_pairs: pair " + std::to_string(i) +
                                    " refers to rect " + std::to_string(worst) + " but there are " +
                                    std::to_string(rect_count) + " rects");
        }
    }
    for (std::size_t i = 0; i < rect_count; ++i) {
        if (!is_finite(rects[i])) {
            throw std::invalid_argument("obbsat::oracle::classify_pairs: rect " + std::to_string(i) +
                                        " has a non-finite coordinate");
        }
    }
}

void classify_range(const rect* rects, const pair_index* pairs, std::size_t begin,
                    std::size_t end, contact* out) {
    for (std::size_t i = begin; i < end; ++i) {
        out[i] = classify(rects[pairs[i].a], rects[pairs[i].b]);
    }
}

}  // namespace

void classify_pairs(const rect* rects, std::size_t rect_count, const pair_index* pairs,
                    std::size_t pair_count, contact* out, unsigned threads) {
    check_inputs(rects, rect_count, pairs, pair_count);
    if (threads == 0) {
        threads = std::max(1u, std::thread::hardware_concurrency());
    }
    // Threads only pay off beyond a few thousand pairs.
    const std::size_t parts =
        std::max<std::size_t>(1, std::min<std::size_t>(threads, pair_count / 4096));
    if (parts == 1) {
        classify_range(rects, pairs, 0, pair_count, out);
        return;
    }
    std::vector<std::thread> workers;
    workers.reserve(parts - 1);
    const std::size_t chunk = (pair_count + parts - 1) / parts;
    for (std::size_t part = 1; part < parts; ++part) {
        const std::size_t begin = part * chunk;
        const std::size_t end = std::min(pair_count, begin + chunk);
        workers.emplace_back(classify_range, rects, pairs, begin, end, out);
    }
    classify_range(rects, pairs, 0, std::min(pair_count, chunk), out);
    for (std::thread& worker : workers) {
        worker.join();
    }
}

std::vector<contact> classify_pairs(const std::vector<rect>& rects,
                                    const std::vector<pair_index>& pairs, unsigned threads) {
    std::vector<contact> out(pairs.size());
    classify_pairs(rects.data(), rects.size(), pairs.data(), pairs.size(), out.data(), threads);
    return out;
}

}  // namespace obbsat::oracle
