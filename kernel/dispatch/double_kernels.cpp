#include "dispatch/backend_catalogue.hpp"
#include "dispatch/compiled_kernels.hpp"
#include "dispatch/double_kernel_table.hpp"

#include <obbsat/oracle/contact64.hpp>
#include <obbsat/oracle/pose_contact64.hpp>
#include <obbsat/ref/certified64.hpp>
#include <obbsat/ref/conservative64.hpp>
#include <obbsat/ref/local64.hpp>
#include <obbsat/ref/pose_conservative64.hpp>

#include <initializer_list>
#include <utility>

namespace obbsat::detail {

namespace {

rect_pose64 pose_at(const double* records, std::size_t i) {
    const double* v = records + 8 * i;
    return rect_pose64{{v[0], v[1]}, {v[2], v[3]}, {v[4], v[5]}};
}

rect64 rect_at(const double* records, std::size_t i) {
    const double* v = records + 8 * i;
    return rect64{{v[0], v[1]}, {v[2], v[3]}, {v[4], v[5]}, {v[6], v[7]}};
}

/// exact on one pair: the certified path, else the oracle (counted in `settled`).
template <class Item>
bool exact_settled(const Item& a, const Item& b, std::size_t& settled) {
    const ref::certified_verdict fast = ref::certify(a, b);
    if (fast.separated || fast.intersecting) {
        return fast.intersecting;
    }
    ++settled;
    return oracle::intersects(a, b);
}

/// verdicts[i] of `m` on the two poses pair_at(i) gives, for i < count.
template <class PairAt>
std::size_t decide_all(method m, std::size_t count, std::uint8_t* verdicts, const PairAt& pair_at) {
    std::size_t settled = 0;
    for (std::size_t i = 0; i < count; ++i) {
        const auto [a, b] = pair_at(i);
        bool v = false;
        switch (m) {
            case method::exact: v = exact_settled(a, b, settled); break;
            case method::conservative: v = ref::conservative(a, b); break;
            default: v = ref::local(a, b); break;  // poses only: the callers admit nothing else
        }
        verdicts[i] = v ? 1 : 0;
    }
    return settled;
}

using pose64_pair = std::pair<rect_pose64, rect_pose64>;

}  // namespace

std::size_t scalar_pose64_indexed(method m, const double* records, const pair_index* pairs, std::size_t count,
                                  std::uint8_t* verdicts) {
    return decide_all(m, count, verdicts, [&](std::size_t i) {
        return pose64_pair{pose_at(records, pairs[i].a), pose_at(records, pairs[i].b)};
    });
}

std::size_t scalar_pose64_stream(method m, const double* a, const double* b, std::size_t count,
                                 std::uint8_t* verdicts) {
    return decide_all(m, count, verdicts, [&](std::size_t i) { return pose64_pair{pose_at(a, i), pose_at(b, i)}; });
}

std::size_t scalar_pose64_stream_soa(method m, const pose_soa64_view& a, const pose_soa64_view& b, std::size_t count,
                                     std::uint8_t* verdicts) {
    return decide_all(m, count, verdicts, [&](std::size_t i) { return pose64_pair{pose64_at(a, i), pose64_at(b, i)}; });
}

std::size_t scalar_rect64_indexed(method m, const double* records, const pair_index* pairs, std::size_t count,
                                  std::uint8_t* verdicts) {
    std::size_t settled = 0;
    for (std::size_t i = 0; i < count; ++i) {
        const rect64 a = rect_at(records, pairs[i].a);
        const rect64 b = rect_at(records, pairs[i].b);
        verdicts[i] = (m == method::exact ? exact_settled(a, b, settled) : ref::conservative(a, b)) ? 1 : 0;
    }
    return settled;
}

namespace {

/// The table `of(Backend{})` gives for `Backend` if it is the SIMD backend
/// `resolved` and its kernels are compiled (compiled_kernels.hpp), else nullptr.
template <class Table, class Backend, class Of>
const Table* table_of_row(backend resolved, const Of& of) {
    if constexpr (Backend::simd && kernels_compiled<Backend>()) {
        return resolved == Backend::id ? &of(Backend{}) : nullptr;
    } else {
        (void)resolved;
        (void)of;
        return nullptr;
    }
}

/// The table `of(Backend{})` gives for the SIMD backend `resolved`, or nullptr
/// for the scalar backend and for a backend whose kernels this build left out.
template <class Table, class Of>
const Table* table_for(backend resolved, const Of& of) {
    for (const Table* found : {table_of_row<Table, avx512_backend>(resolved, of),
                               table_of_row<Table, avx2_backend>(resolved, of),
                               table_of_row<Table, sse2_backend>(resolved, of)}) {
        if (found != nullptr) {
            return found;
        }
    }
    return nullptr;
}

}  // namespace

const double_kernel_table* double_kernels_for(backend resolved) {
    return table_for<double_kernel_table>(
        resolved, [](auto row) -> const double_kernel_table& { return double_kernels_of<decltype(row)>(); });
}

const corner64_kernel_table* corner64_kernels_for(backend resolved) {
    return table_for<corner64_kernel_table>(
        resolved, [](auto row) -> const corner64_kernel_table& { return corner64_kernels_of<decltype(row)>(); });
}

}  // namespace obbsat::detail
