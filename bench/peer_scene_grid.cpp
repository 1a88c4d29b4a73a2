// A uniform grid as a scene peer: the broadphase a game programmer writes
// first (as examples/scene does), then obbsat's exact narrowphase on the
// candidates (scene_narrowphase.hpp). Written here afresh, not shared with the
// example.
//
// Each query: the obbsat bounds of every box (obbsat::ref::bounds_of, so the
// candidates are exactly the pairs find_pairs considers); a square cell a
// little wider than the widest box, so two boxes whose bounds overlap have
// their bounds' centres in the same or in neighbouring cells; every box filed
// under its centre's cell by a counting sort, with its bounds copied into cell
// order; then each cell against itself and four of its neighbours (right, and
// the three above), so every pair of cells is visited once. Nothing is kept
// between frames but the buffers: a grid is rebuilt on every step.
//
// The cell follows the widest box, which suits uniform sizes; with mixed sizes
// (two decades) a cell holds tens of boxes and the rows show what that costs.
#include "bench_registry.hpp"
#include "scene_harness.hpp"
#include "scene_narrowphase.hpp"
#include "scene_parts.hpp"
#include "scene_workload.hpp"

#include <obbsat/pose_records.hpp>
#include <obbsat/ref/bounds.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <memory>
#include <vector>

namespace obbsat_bench {

namespace {

struct filed_box {
    obbsat::ref::box_bounds bounds;
    std::uint32_t index;
};

class grid_query final : public scene_query {
public:
    grid_query(scene_workload& scene, unsigned threads) : scene_(&scene), parts_(threads) {}

    const std::vector<obbsat::pair_index>& find(scene_frame f) override {
        const obbsat::pose_records& poses = scene_->poses(f);
        file_boxes(poses);
        const auto parts = static_cast<unsigned>(parts_.size());
        run_parts(parts, [this, &poses, parts](unsigned part) {
            const part_range rows = part_of(rows_, parts, part);
            part_pairs& mine = parts_[part];
            mine.candidates.clear();
            for (std::size_t row = rows.begin; row < rows.end; ++row) {
                for (std::size_t column = 0; column < columns_; ++column) {
                    visit_cell(column, row, mine.candidates);
                }
            }
            decide_exact(poses, mine);
        });
        candidates_ = join_parts(parts_, pairs_);
        return pairs_;
    }

    std::size_t candidates() const override { return candidates_; }

private:
    /// Bounds, cell size and a counting sort of the boxes by cell.
    void file_boxes(const obbsat::pose_records& poses) {
        const std::size_t n = poses.size();
        bounds_.resize(n);
        centres_.resize(n);
        float widest = 0.0f;
        float lo_x = INFINITY, lo_y = INFINITY, hi_x = -INFINITY, hi_y = -INFINITY;
        for (std::size_t i = 0; i < n; ++i) {
            const obbsat::ref::box_bounds b = obbsat::ref::bounds_of(poses[i]);
            bounds_[i] = b;
            widest = std::max({widest, b.hi_x - b.lo_x, b.hi_y - b.lo_y});
            const float cx = 0.5f * (b.lo_x + b.hi_x);
            const float cy = 0.5f * (b.lo_y + b.hi_y);
            centres_[i] = {cx, cy};
            lo_x = std::min(lo_x, cx);
            lo_y = std::min(lo_y, cy);
            hi_x = std::max(hi_x, cx);
            hi_y = std::max(hi_y, cy);
        }
        if (n == 0) {
            columns_ = rows_ = 0;
            cell_start_.assign(1, 0);
            return;
        }
        // Two overlapping bounds have centres at most `widest` apart, plus
        // the centres' rounding (2^-24 of their magnitude each); the margin
        // covers that and the rounding of the cell coordinates below. Any
        // wider cell is correct too, so a cell is widened until the grid has
        // at most a few cells per box.
        const double reach = std::max({std::fabs(lo_x), std::fabs(lo_y), std::fabs(hi_x), std::fabs(hi_y)});
        cell_ = static_cast<double>(widest) * (1.0 + 0x1p-10) + reach * 0x1p-20 + 0x1p-100;
        origin_x_ = lo_x;
        origin_y_ = lo_y;
        for (;;) {
            columns_ = static_cast<std::size_t>((static_cast<double>(hi_x) - origin_x_) / cell_) + 1;
            rows_ = static_cast<std::size_t>((static_cast<double>(hi_y) - origin_y_) / cell_) + 1;
            if (columns_ * rows_ <= 4 * n + 64) {
                break;
            }
            cell_ *= 2.0;
        }
        cell_start_.assign(columns_ * rows_ + 1, 0);
        cell_of_.resize(n);
        for (std::size_t i = 0; i < n; ++i) {
            const std::size_t column =
                std::min(columns_ - 1, static_cast<std::size_t>((static_cast<double>(centres_[i].x) - origin_x_) / cell_));
            const std::size_t row =
                std::min(rows_ - 1, static_cast<std::size_t>((static_cast<double>(centres_[i].y) - origin_y_) / cell_));
            cell_of_[i] = static_cast<std::uint32_t>(row * columns_ + column);
            ++cell_start_[cell_of_[i] + 1];
        }
        for (std::size_t c = 0; c + 1 < cell_start_.size(); ++c) {
            cell_start_[c + 1] += cell_start_[c];
        }
        fill_.assign(cell_start_.begin(), cell_start_.end() - 1);
        filed_.resize(n);
        for (std::size_t i = 0; i < n; ++i) {
            filed_[fill_[cell_of_[i]]++] = {bounds_[i], static_cast<std::uint32_t>(i)};
        }
    }

    void visit_cell(std::size_t column, std::size_t row, std::vector<obbsat::pair_index>& out) const {
        const std::size_t cell = row * columns_ + column;
        const std::size_t begin = cell_start_[cell];
        const std::size_t end = cell_start_[cell + 1];
        for (std::size_t p = begin; p < end; ++p) {
            for (std::size_t q = p + 1; q < end; ++q) {
                add_if_overlapping(filed_[p], filed_[q], out);
            }
        }
        // Right, then the row above: left, straight up, right.
        const bool right = column + 1 < columns_;
        const bool above = row + 1 < rows_;
        const bool left = column > 0;
        if (right) {
            visit_pair(cell, cell + 1, out);
        }
        if (above) {
            if (left) {
                visit_pair(cell, cell + columns_ - 1, out);
            }
            visit_pair(cell, cell + columns_, out);
            if (right) {
                visit_pair(cell, cell + columns_ + 1, out);
            }
        }
    }

    void visit_pair(std::size_t cell, std::size_t other, std::vector<obbsat::pair_index>& out) const {
        for (std::size_t p = cell_start_[cell]; p < cell_start_[cell + 1]; ++p) {
            for (std::size_t q = cell_start_[other]; q < cell_start_[other + 1]; ++q) {
                add_if_overlapping(filed_[p], filed_[q], out);
            }
        }
    }

    static void add_if_overlapping(const filed_box& a, const filed_box& b, std::vector<obbsat::pair_index>& out) {
        if (obbsat::ref::bounds_overlap(a.bounds, b.bounds)) {
            out.push_back({std::min(a.index, b.index), std::max(a.index, b.index)});
        }
    }

    scene_workload* scene_;
    std::vector<part_pairs> parts_;
    std::vector<obbsat::ref::box_bounds> bounds_;
    std::vector<obbsat::point> centres_;
    std::vector<std::uint32_t> cell_of_;
    std::vector<std::size_t> cell_start_;
    std::vector<std::size_t> fill_;
    std::vector<filed_box> filed_;
    double cell_ = 1.0;
    double origin_x_ = 0.0;
    double origin_y_ = 0.0;
    std::size_t columns_ = 0;
    std::size_t rows_ = 0;
    std::size_t candidates_ = 0;
    std::vector<obbsat::pair_index> pairs_;
};

}  // namespace

void register_grid_scene_peer() {
    scene_rows rows;
    rows.cold_prefix = "peer_scene/grid";
    rows.frame_prefix = "peer_frame/grid";
    rows.thread_counts = {1, 2};
    rows.expected = {obbsat::store_kind::poses, obbsat::method::exact, true};
    rows.prepare = [](scene_workload& w, scene_row_kind) -> scene_query_factory {
        return [&w](unsigned threads) -> std::unique_ptr<scene_query> {
            return std::make_unique<grid_query>(w, threads);
        };
    };
    register_scene_rows(rows);
}

}  // namespace obbsat_bench
