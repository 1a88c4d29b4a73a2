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

void check_shape(const rect& r, std::size_t i) {
    if (!is_finite(r)) {
        throw std::invalid_argument("obbsat::oracle::classify_pairs: rect " + std::to_string(i) +
                                    " has a non-finite coordinate");
    }
}

void check_shape(const rect_pose& p, std::size_t i) {
    if (const char* defect = pose_defect(p)) {
        throw std::invalid_argument("obbsat::oracle::classify_pairs: pose " + std::to_string(i) +
                                    " is invalid: " + defect);
    }
}

template <class Shape>
void check_inputs(const char* shape_name, const Shape* shapes, std::size_t shape_count,
                  const pair_index* pairs, std::size_t pair_count) {
    for (std::size_t i = 0; i < pair_count; ++i) {
        const std::uint32_t worst = std::max(pairs[i].a, pairs[i].b);
        if (worst >= shape_count) {
            throw std::out_of_range("obbsat::oracle::classify_pairs: pair " + std::to_string(i) +
                                    " refers to " + shape_name + " " + std::to_string(worst) +
                                    " but there are " + std::to_string(shape_count) + " " +
                                    shape_name + "s");
        }
    }
    for (std::size_t i = 0; i < shape_count; ++i) {
        check_shape(shapes[i], i);
    }
}

template <class Shape>
void classify_range(const Shape* shapes, const pair_index* pairs, std::size_t begin,
                    std::size_t end, contact* out) {
    for (std::size_t i = begin; i < end; ++i) {
        out[i] = classify(shapes[pairs[i].a], shapes[pairs[i].b]);
    }
}

// The pairs split into one contiguous range per thread, the calling thread
// taking the first.
template <class Shape>
void classify_split(const Shape* shapes, const pair_index* pairs, std::size_t pair_count,
                    contact* out, unsigned threads) {
    if (threads == 0) {
        threads = std::max(1u, std::thread::hardware_concurrency());
    }
    // Threads only pay off beyond a few thousand pairs.
    const std::size_t parts =
        std::max<std::size_t>(1, std::min<std::size_t>(threads, pair_count / 4096));
    if (parts == 1) {
        classify_range(shapes, pairs, 0, pair_count, out);
        return;
    }
    std::vector<std::thread> workers;
    workers.reserve(parts - 1);
    const std::size_t chunk = (pair_count + parts - 1) / parts;
    for (std::size_t part = 1; part < parts; ++part) {
        const std::size_t begin = part * chunk;
        const std::size_t end = std::min(pair_count, begin + chunk);
        workers.emplace_back(classify_range<Shape>, shapes, pairs, begin, end, out);
    }
    classify_range(shapes, pairs, 0, std::min(pair_count, chunk), out);
    for (std::thread& worker : workers) {
        worker.join();
    }
}

}  // namespace

void classify_pairs(const rect* rects, std::size_t rect_count, const pair_index* pairs,
                    std::size_t pair_count, contact* out, unsigned threads) {
    check_inputs("rect", rects, rect_count, pairs, pair_count);
    classify_split(rects, pairs, pair_count, out, threads);
}

std::vector<contact> classify_pairs(const std::vector<rect>& rects,
                                    const std::vector<pair_index>& pairs, unsigned threads) {
    std::vector<contact> out(pairs.size());
    classify_pairs(rects.data(), rects.size(), pairs.data(), pairs.size(), out.data(), threads);
    return out;
}

void classify_pairs(const rect_pose* poses, std::size_t pose_count, const pair_index* pairs,
                    std::size_t pair_count, contact* out, unsigned threads) {
    check_inputs("pose", poses, pose_count, pairs, pair_count);
    classify_split(poses, pairs, pair_count, out, threads);
}

std::vector<contact> classify_pairs(const std::vector<rect_pose>& poses,
                                    const std::vector<pair_index>& pairs, unsigned threads) {
    std::vector<contact> out(pairs.size());
    classify_pairs(poses.data(), poses.size(), pairs.data(), pairs.size(), out.data(), threads);
    return out;
}

}  // namespace obbsat::oracle
