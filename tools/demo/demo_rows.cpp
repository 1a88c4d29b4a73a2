#include "demo/demo_rows.hpp"

#include <obbsat/backend.hpp>
#include <obbsat/collide.hpp>
#include <obbsat/pose.hpp>

#include <algorithm>
#include <cstring>
#include <utility>

namespace obbsat::cli {

namespace {

// The method and store groups to time, in table order: by the declaration
// order of each method's corner counterpart, corners before poses.
std::vector<std::pair<method, store_kind>> group_order(const std::vector<method>& methods) {
    const std::vector<method> order = all_methods();
    const auto rank = [&order](method m) {
        return std::find(order.begin(), order.end(), corner_counterpart(m)) - order.begin();
    };
    std::vector<std::pair<method, store_kind>> groups;
    for (const method m : methods) {
        for (const store_kind kind : {store_kind::corners, store_kind::poses}) {
            if (runs_on(m, kind)) {
                groups.emplace_back(m, kind);
            }
        }
    }
    std::stable_sort(groups.begin(), groups.end(), [&rank](const auto& x, const auto& y) {
        return rank(x.first) < rank(y.first) ||
               (rank(x.first) == rank(y.first) && x.second == store_kind::corners &&
                y.second == store_kind::poses);
    });
    return groups;
}

collide_options options_for(method test, backend b, unsigned threads) {
    collide_options options;
    options.test = test;
    options.use = b;
    options.threads = threads;
    return options;
}

}  // namespace

std::vector<backend> runnable_backends() {
    std::vector<backend> runnable{backend::scalar};
    const std::vector<backend> compiled = compiled_backends();  // best first
    for (auto b = compiled.rbegin(); b != compiled.rend(); ++b) {
        if (*b != backend::scalar && cpu_supports(*b)) {
            runnable.push_back(*b);
        }
    }
    return runnable;
}

method corner_counterpart(method m) { return m == method::local ? method::sat4 : m; }

std::vector<demo_group> demo_groups(const demo_scene& demo, const std::vector<method>& methods) {
    std::vector<demo_group> groups;
    const std::vector<pair_index>& pairs = demo.world.pairs;
    for (const auto& [test, kind] : group_order(methods)) {
        demo_group group{test, kind, "", nullptr, {}};
        if (kind == store_kind::corners) {
            group.reference_name = "the scalar reference (the scalar backend over soa at 1 thread)";
            const collide_options reference = options_for(test, backend::scalar, 1);
            group.reference = [&demo, &pairs, reference](std::uint8_t* verdicts) {
                collide_pairs(demo.world.rects, pairs.data(), pairs.size(), verdicts, reference);
            };
            for (const char* store : {"soa", "records"}) {
                const bool soa = std::strcmp(store, "soa") == 0;
                for (const backend b : runnable_backends()) {
                    for (const unsigned threads : {1u, 2u}) {
                        const collide_options options = options_for(test, b, threads);
                        auto run = [&demo, &pairs, soa, options](std::uint8_t* verdicts) {
                            if (soa) {
                                collide_pairs(demo.world.rects, pairs.data(), pairs.size(), verdicts,
                                              options);
                            } else {
                                collide_pairs(demo.records, pairs.data(), pairs.size(), verdicts,
                                              options);
                            }
                        };
                        group.entries.push_back(demo_entry{backend_name(b), store, threads, run});
                    }
                }
            }
        } else {
            group.reference_name = "the scalar reference on poses (obbsat::pose_method_reference)";
            const pose_reference_fn reference = pose_method_reference(test);
            group.reference = [&demo, &pairs, reference](std::uint8_t* verdicts) {
                for (std::size_t i = 0; i < pairs.size(); ++i) {
                    verdicts[i] = reference(demo.poses[pairs[i].a], demo.poses[pairs[i].b]) ? 1 : 0;
                }
            };
            for (const backend b : runnable_backends()) {
                for (const unsigned threads : {1u, 2u}) {
                    const collide_options options = options_for(test, b, threads);
                    auto run = [&demo, &pairs, options](std::uint8_t* verdicts) {
                        collide_pairs(demo.poses, pairs.data(), pairs.size(), verdicts, options);
                    };
                    group.entries.push_back(demo_entry{backend_name(b), "poses", threads, run});
                }
            }
        }
        // ---- More rows for this method go here. --------------------------
        // A peer implementation (another library's test on the same scene) is
        // one more demo_entry with its own `runner` name and a `run` that
        // writes one 0/1 byte per pair of demo.world.pairs; it is then checked
        // against the group's reference and timed like every backend. Only add
        // rows that really run: every figure in the table is measured here.
        // -------------------------------------------------------------------
        groups.push_back(std::move(group));
    }
    return groups;
}

const measured_row* find_row(const std::vector<measured_row>& rows, method test, const char* store,
                             const char* runner, unsigned threads) {
    for (const measured_row& row : rows) {
        if (row.test == test && row.store == store && row.runner == runner && row.threads == threads) {
            return &row;
        }
    }
    return nullptr;
}

double median_of(std::vector<double> values) {
    std::sort(values.begin(), values.end());
    const std::size_t mid = values.size() / 2;
    return values.size() % 2 == 1 ? values[mid] : 0.5 * (values[mid - 1] + values[mid]);
}

}  // namespace obbsat::cli
