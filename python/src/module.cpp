// obbsat._core: the compiled half of the Python module. It takes numpy arrays
// whose memory already has the library's layout (the package's __init__.py
// converts anything else, once, before calling here), checks that layout
// again, releases the GIL and calls the C++ entry points. Shapes, dtypes and
// names are the Python layer's business; this file only refuses what would be
// unsafe to read or write.
//
// Two stores: corners (rows of eight floats, read in place or kept in a
// rect_records) and poses (rows of six floats cx, cy, hx, hy, c, s, read in
// place by pair-list calls, copied into a pose_soa for streams, or kept in a
// pose_records). float64 rows go to the double stores of each kind
// (rect_records64, pose_records64), copied once per pair-list call or kept
// in a RectRecords64 or PoseRecords64; a store kept from Python is decided
// on the same library path as an array of its rows, so the verdicts are
// the same bytes. A method is checked against the store before anything is
// read or copied.
//
// Scene queries (find_pairs, PairFinder) take one or two sets of one kind:
// a store passed in (store_traits names the four), or the rows of an array,
// which the library's scene query reads in place (obbsat::box_view) and
// checks in the pass that computes the bounds. Each side may carry pair filters
// (obbsat/pair_filters.hpp): categories and masks as uint64, groups as
// int32, read in place when they already are, else converted here without
// loss (a value that does not fit is a ValueError). The pairs come back
// in the vector the library filled, owned by the numpy array (no copy), or,
// from a PairFinder, copied out of the finder's reused buffer (its begin/end
// events too).
//
// Errors: obbsat::invalid_input becomes IndexError when it names a pair (an
// index out of range) and ValueError otherwise (a non-finite coordinate, a bad
// pose field, a method that does not run on the store, batches of unequal
// length); obbsat::unsupported_backend becomes obbsat.UnsupportedBackendError,
// a ValueError. Nothing is written then.
#include "contacts_module.hpp"

#include <obbsat/backend.hpp>
#include <obbsat/collide.hpp>
#include <obbsat/collide64.hpp>
#include <obbsat/error.hpp>
#include <obbsat/find_contacts.hpp>
#include <obbsat/find_pairs.hpp>
#include <obbsat/method.hpp>
#include <obbsat/pose_conversion.hpp>
#include <obbsat/pose_records.hpp>
#include <obbsat/pose_scene.hpp>
#include <obbsat/pose_soa.hpp>
#include <obbsat/rect.hpp>
#include <obbsat/rect_pose.hpp>
#include <obbsat/rect_records.hpp>
#include <obbsat/rect_soa.hpp>
#include <obbsat/ref/bounds.hpp>
#include <obbsat/ref/bounds64.hpp>
#include <obbsat/scene.hpp>

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <limits>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace py = pybind11;

namespace {

static_assert(sizeof(obbsat::rect) == 8 * sizeof(float), "a rect is eight packed floats");
static_assert(sizeof(obbsat::pair_index) == 2 * sizeof(std::uint32_t), "a pair is two packed uint32");
// A row cx, cy, hx, hy, c, s of a float32 (N, 6) array is one rect_pose, so
// the pose stores copy from the caller's array with no temporary.
static_assert(sizeof(obbsat::rect_pose) == obbsat::pose_field_count * sizeof(float) &&
                  std::is_standard_layout<obbsat::rect_pose>::value,
              "a rect_pose is six packed floats cx, cy, hx, hy, c, s");

obbsat::method method_named(const std::string& name) {
    const auto m = obbsat::parse_method(name);
    if (!m) {
        std::string known;
        for (const obbsat::method each : obbsat::all_methods()) {
            known += known.empty() ? "" : ", ";
            known += obbsat::method_name(each);
        }
        throw py::value_error("unknown method '" + name + "' (known: " + known + ")");
    }
    return *m;
}

obbsat::backend backend_named(const std::string& name) {
    const auto b = obbsat::parse_backend(name);
    if (!b) {
        std::string known = "auto";
        for (const obbsat::backend each : obbsat::compiled_backends()) {
            known += std::string(", ") + obbsat::backend_name(each);
        }
        throw py::value_error("unknown backend '" + name + "' (known: " + known + ")");
    }
    return *b;
}

obbsat::collide_options options_of(const std::string& method, const std::string& backend, long long threads) {
    // collide_options::threads is unsigned: a larger count would wrap around.
    constexpr long long most_threads = std::numeric_limits<unsigned>::max();
    if (threads < 0 || threads > most_threads) {
        throw py::value_error("threads must be >= 0 and <= " + std::to_string(most_threads) +
                              " (0 means every core), not " + std::to_string(threads));
    }
    obbsat::collide_options options;
    options.test = method_named(method);
    options.use = backend_named(backend);
    options.threads = static_cast<unsigned>(threads);
    return options;
}

bool is_c_contiguous(const py::array& a) {
    return (a.flags() & py::array::c_style) != 0;
}

/// True iff the elements of `a` are T in native byte order.
template <class T>
bool holds(const py::array& a) {
    return py::isinstance<py::array_t<T>>(a);
}

/// The rectangles of `a`, read in place: float32, native order, C-contiguous,
/// eight floats per row (shape (N, 8) or (N, 4, 2)).
std::pair<const obbsat::rect*, std::size_t> corners_in_place(const py::array& a, const char* what) {
    const bool shape_ok = (a.ndim() == 2 && a.shape(1) == 8) ||
                          (a.ndim() == 3 && a.shape(1) == 4 && a.shape(2) == 2);
    if (!shape_ok || !holds<float>(a) || !is_c_contiguous(a)) {
        throw py::type_error(std::string(what) +
                             ": expected a C-contiguous float32 array of shape (N, 8) or (N, 4, 2)");
    }
    return {static_cast<const obbsat::rect*>(a.data()), static_cast<std::size_t>(a.shape(0))};
}

/// The poses of `a`, read in place: float32, native order, C-contiguous, shape (N, 6).
std::pair<const obbsat::rect_pose*, std::size_t> poses_in_place(const py::array& a, const char* what) {
    if (a.ndim() != 2 || a.shape(1) != 6 || !holds<float>(a) || !is_c_contiguous(a)) {
        throw py::type_error(std::string(what) + ": expected a C-contiguous float32 array of shape (N, 6)");
    }
    return {static_cast<const obbsat::rect_pose*>(a.data()), static_cast<std::size_t>(a.shape(0))};
}

/// The double rectangles of `a`, read in place: float64, native order,
/// C-contiguous, eight doubles per row (shape (N, 8) or (N, 4, 2)).
std::pair<const obbsat::rect64*, std::size_t> corners64_in_place(const py::array& a, const char* what) {
    const bool shape_ok = (a.ndim() == 2 && a.shape(1) == 8) ||
                          (a.ndim() == 3 && a.shape(1) == 4 && a.shape(2) == 2);
    if (!shape_ok || !holds<double>(a) || !is_c_contiguous(a)) {
        throw py::type_error(std::string(what) +
                             ": expected a C-contiguous float64 array of shape (N, 8) or (N, 4, 2)");
    }
    return {static_cast<const obbsat::rect64*>(a.data()), static_cast<std::size_t>(a.shape(0))};
}

/// The double poses of `a`, read in place: float64, native order, C-contiguous, shape (N, 6).
std::pair<const obbsat::rect_pose64*, std::size_t> poses64_in_place(const py::array& a, const char* what) {
    if (a.ndim() != 2 || a.shape(1) != 6 || !holds<double>(a) || !is_c_contiguous(a)) {
        throw py::type_error(std::string(what) + ": expected a C-contiguous float64 array of shape (N, 6)");
    }
    return {static_cast<const obbsat::rect_pose64*>(a.data()), static_cast<std::size_t>(a.shape(0))};
}

/// The pairs of `a`, read in place: uint32, native order, C-contiguous, shape (M, 2).
std::pair<const obbsat::pair_index*, std::size_t> pairs_in_place(const py::array& a) {
    if (a.ndim() != 2 || a.shape(1) != 2 || !holds<std::uint32_t>(a) ||
        !is_c_contiguous(a)) {
        throw py::type_error("pairs: expected a C-contiguous uint32 array of shape (M, 2)");
    }
    return {static_cast<const obbsat::pair_index*>(a.data()), static_cast<std::size_t>(a.shape(0))};
}

/// The verdict bytes of `out`: one byte per item (uint8 or bool), C-contiguous, writable, `count` long.
std::uint8_t* verdicts_in_place(py::array& out, std::size_t count) {
    if (out.ndim() != 1 || out.itemsize() != 1 || (out.dtype().kind() != 'u' && out.dtype().kind() != 'b') ||
        !is_c_contiguous(out) || !out.writeable()) {
        throw py::type_error("out: expected a writable, C-contiguous 1-D array of dtype bool or uint8");
    }
    if (static_cast<std::size_t>(out.shape(0)) != count) {
        throw py::value_error("out: holds " + std::to_string(out.shape(0)) + " verdicts, " +
                              std::to_string(count) + " needed");
    }
    return static_cast<std::uint8_t*>(out.mutable_data());
}

/// The bytes [first, last) that `a`'s elements span, whatever its strides.
std::pair<std::uintptr_t, std::uintptr_t> byte_span(const py::array& a) {
    auto first = reinterpret_cast<std::uintptr_t>(a.data());
    auto last = first;
    if (a.size() == 0) {
        return {first, first};
    }
    for (py::ssize_t axis = 0; axis < a.ndim(); ++axis) {
        const py::ssize_t step = a.strides(axis) * (a.shape(axis) - 1);
        if (step < 0) {
            first -= static_cast<std::uintptr_t>(-step);
        } else {
            last += static_cast<std::uintptr_t>(step);
        }
    }
    return {first, last + static_cast<std::uintptr_t>(a.itemsize())};
}

/// Refuses an `out` whose bytes share memory with the input `what`, which
/// the call would overwrite while (or before) reading it: ValueError naming both.
void require_apart(const py::array& out, const py::array& input, const char* what) {
    const auto [out_first, out_last] = byte_span(out);
    const auto [in_first, in_last] = byte_span(input);
    if (out_first < out_last && in_first < in_last && out_first < in_last && in_first < out_last) {
        throw py::value_error(std::string("out and ") + what + " share memory: out must not overlap " + what);
    }
}

/// Runs `call` without the GIL and returns what it returns, turning the
/// library's exceptions into Python's.
template <class Call>
auto without_gil(const Call& call) -> decltype(call()) {
    std::string invalid;
    std::string unsupported;
    std::optional<decltype(call())> result;
    {
        py::gil_scoped_release release;
        try {
            result.emplace(call());
        } catch (const obbsat::invalid_input& e) {
            invalid = e.what();
        } catch (const obbsat::unsupported_backend& e) {
            unsupported = e.what();
        }
    }
    if (!unsupported.empty()) {
        throw obbsat::unsupported_backend(unsupported);
    }
    if (!invalid.empty()) {
        if (invalid.rfind("pair ", 0) == 0) {
            throw py::index_error(invalid);
        }
        throw py::value_error(invalid);
    }
    return std::move(*result);
}

/// Throws the library's invalid_input when options.test does not run on
/// `store`: it is the refusal of an empty batch over that store, so the
/// message is the library's own and nothing has been read or copied yet.
void require_runs_on(const obbsat::collide_options& options, obbsat::store_kind store) {
    if (obbsat::runs_on(options.test, store)) {
        return;
    }
    if (store == obbsat::store_kind::poses) {
        obbsat::collide_pairs(obbsat::pose_records{}, nullptr, 0, nullptr, options);
    } else {
        obbsat::collide_pairs(obbsat::rect_records{}, nullptr, 0, nullptr, options);
    }
}

/// Throws invalid_input when options.test does not run on float64 rows of
/// `store`, naming the method, the dtype and the methods that do.
void require_runs_on_doubles(const obbsat::collide_options& options, obbsat::store_kind store) {
    if (obbsat::runs_on_doubles(options.test, store)) {
        return;
    }
    std::string offered;
    for (const obbsat::method m : obbsat::methods_on_doubles(store)) {
        offered += std::string(offered.empty() ? "" : ", ") + obbsat::method_name(m);
    }
    throw obbsat::invalid_input(std::string("method ") + obbsat::method_name(options.test) + " does not run on float64 " +
                                (store == obbsat::store_kind::poses ? "poses" : "corners") + " (they take " + offered +
                                "); to decide them rounded to float32, pass precision=\"float32\" (for a store, "
                                "build it with obbsat.records(rows, precision=\"float32\"))");
}

/// What each kind of store holds and reads from an array, and how Python
/// names it. A store's records lie record_bytes apart, each starting with
/// its `fields` values (a pose record ends in padding).
template <class Store>
struct store_traits;

/// What a store's traits follow from its form and its value type: the row
/// width, the name of its rows, and the methods it takes (those that run on
/// doubles for a double store).
template <obbsat::store_kind Kind, class Value>
struct store_form {
    using value = Value;
    static constexpr obbsat::store_kind kind = Kind;
    static constexpr bool poses = Kind == obbsat::store_kind::poses;
    static constexpr std::size_t fields = poses ? obbsat::pose_field_count : 8;
    static constexpr const char* rows_name = poses ? "poses" : "corners";
    static void require_method(const obbsat::collide_options& options) {
        if (std::is_same<Value, double>::value) {
            require_runs_on_doubles(options, Kind);
        } else {
            require_runs_on(options, Kind);
        }
    }
};

template <>
struct store_traits<obbsat::rect_records> : store_form<obbsat::store_kind::corners, float> {
    using row = obbsat::rect;
    static constexpr std::size_t record_bytes = sizeof(obbsat::rect);
    static constexpr const char* class_name = "RectRecords";
    static constexpr auto rows_in_place = &corners_in_place;
};

template <>
struct store_traits<obbsat::pose_records> : store_form<obbsat::store_kind::poses, float> {
    using row = obbsat::rect_pose;
    static constexpr std::size_t record_bytes = obbsat::pose_records::record_floats * sizeof(float);
    static constexpr const char* class_name = "PoseRecords";
    static constexpr auto rows_in_place = &poses_in_place;
};

template <>
struct store_traits<obbsat::rect_records64> : store_form<obbsat::store_kind::corners, double> {
    using row = obbsat::rect64;
    static constexpr std::size_t record_bytes = sizeof(obbsat::rect64);
    static constexpr const char* class_name = "RectRecords64";
    static constexpr auto rows_in_place = &corners64_in_place;
};

template <>
struct store_traits<obbsat::pose_records64> : store_form<obbsat::store_kind::poses, double> {
    using row = obbsat::rect_pose64;
    static constexpr std::size_t record_bytes = obbsat::pose_records64::record_doubles * sizeof(double);
    static constexpr const char* class_name = "PoseRecords64";
    static constexpr auto rows_in_place = &poses64_in_place;
};

/// A store holding a checked copy of the rows of `rows` (read in place; a
/// bad row is a ValueError naming the row and the field).
template <class Store>
Store store_of(const py::array& rows) {
    using traits = store_traits<Store>;
    const auto [list, count] = traits::rows_in_place(rows, traits::rows_name);
    return without_gil([&, list = list, count = count] { return Store(list, count); });
}

/// The records of `store` as bytes, record_bytes apart.
template <class Store>
const unsigned char* record_bytes_of(const Store& store) {
    return reinterpret_cast<const unsigned char*>(store.data());
}

/// The rows of `store` as a read-only (N, fields) array over its own
/// records (rows record_bytes apart), kept alive by `owner`.
template <class Store>
py::array rows_view(const Store& store, py::handle owner) {
    using traits = store_traits<Store>;
    using value = typename traits::value;
    py::array_t<value> view({static_cast<py::ssize_t>(store.size()), static_cast<py::ssize_t>(traits::fields)},
                            {static_cast<py::ssize_t>(traits::record_bytes), static_cast<py::ssize_t>(sizeof(value))},
                            reinterpret_cast<const value*>(record_bytes_of(store)), owner);
    view.attr("setflags")(py::arg("write") = false);
    return std::move(view);
}

/// The rows of `store` as a new C-contiguous (N, fields) array: its pickled state.
template <class Store>
py::array_t<typename store_traits<Store>::value> rows_copy(const Store& store) {
    using traits = store_traits<Store>;
    using value = typename traits::value;
    py::array_t<value> copy({static_cast<py::ssize_t>(store.size()), static_cast<py::ssize_t>(traits::fields)});
    auto* out = reinterpret_cast<unsigned char*>(copy.mutable_data());
    const unsigned char* records = record_bytes_of(store);
    constexpr std::size_t row_bytes = traits::fields * sizeof(value);
    for (std::size_t i = 0; i < store.size(); ++i) {
        std::memcpy(out + i * row_bytes, records + i * traits::record_bytes, row_bytes);
    }
    return copy;
}

/// Verdicts of pairs over a prepared store: its rows were checked when it
/// was built, so the call reads only the pairs before deciding them, on the
/// same library path as an array of its rows.
template <class Store>
std::string collide_store(const Store& store, const py::array& pairs, py::array& out, const std::string& method,
                          const std::string& backend, long long threads) {
    const obbsat::collide_options options = options_of(method, backend, threads);
    const auto [pair_list, count] = pairs_in_place(pairs);
    std::uint8_t* verdicts = verdicts_in_place(out, count);
    require_apart(out, pairs, "pairs");
    const obbsat::backend ran = without_gil([&, pair_list = pair_list, count = count] {
        store_traits<Store>::require_method(options);
        return obbsat::collide_pairs(store, pair_list, count, verdicts, options);
    });
    return obbsat::backend_name(ran);
}

/// Registers the Python class of the store kind Store: built from an array
/// of its rows (checked once), its length, a read-only view of its rows, a
/// repr, and pickling as its rows.
template <class Store>
void def_store(py::module_& m, const char* doc, const char* init_doc, const char* view_doc) {
    using traits = store_traits<Store>;
    py::class_<Store>(m, traits::class_name, doc)
        .def(py::init(&store_of<Store>), py::arg(traits::rows_name), init_doc)
        .def("__len__", &Store::size)
        .def_property_readonly(
            traits::rows_name, [](py::object self) { return rows_view(self.cast<const Store&>(), self); }, view_doc)
        .def("__repr__",
             [](const Store& store) {
                 return std::string(traits::class_name) + "(" + std::to_string(store.size()) + " " +
                        (traits::poses ? "poses" : "rectangles") + ")";
             })
        .def(py::pickle([](const Store& store) { return py::make_tuple(rows_copy(store)); },
                        [](const py::tuple& state) {
                            if (state.size() != 1) {
                                throw py::value_error(std::string(traits::class_name) + ": bad pickled state");
                            }
                            return store_of<Store>(state[0].cast<py::array>());
                        }));
}

/// A double store holding a checked copy of `count` rows; the error is prefixed "what: " when `what` is given.
template <class Store, class Row>
Store double_store(const Row* rows, std::size_t count, const char* what) {
    try {
        return Store(rows, count);
    } catch (const obbsat::invalid_input& e) {
        if (what == nullptr) {
            throw;
        }
        throw obbsat::invalid_input(std::string(what) + ": " + e.what());
    }
}

/// Verdicts of pairs over float64 rows (corners or poses), copied once into the double store.
template <class Store, class Row>
std::string collide_doubles(const std::pair<const Row*, std::size_t>& rows, const py::array& rows_array,
                            const char* what, obbsat::store_kind kind, const py::array& pairs, py::array& out,
                            const std::string& method, const std::string& backend, long long threads) {
    const obbsat::collide_options options = options_of(method, backend, threads);
    const auto [pair_list, count] = pairs_in_place(pairs);
    std::uint8_t* verdicts = verdicts_in_place(out, count);
    require_apart(out, rows_array, what);
    require_apart(out, pairs, "pairs");
    const obbsat::backend ran = without_gil([&, pair_list = pair_list, count = count] {
        require_runs_on_doubles(options, kind);
        const Store store = double_store<Store>(rows.first, rows.second, nullptr);
        return obbsat::collide_pairs(store, pair_list, count, verdicts, options);
    });
    return obbsat::backend_name(ran);
}

std::string collide_records64(const py::array& rects, const py::array& pairs, py::array& out,
                              const std::string& method, const std::string& backend, long long threads) {
    return collide_doubles<obbsat::rect_records64>(corners64_in_place(rects, "rects"), rects, "rects",
                                                   obbsat::store_kind::corners, pairs, out, method, backend, threads);
}

std::string collide_poses64(const py::array& poses, const py::array& pairs, py::array& out,
                            const std::string& method, const std::string& backend, long long threads) {
    return collide_doubles<obbsat::pose_records64>(poses64_in_place(poses, "poses"), poses, "poses",
                                                   obbsat::store_kind::poses, pairs, out, method, backend, threads);
}

/// Verdicts of a[i] against b[i] over float64 rows: poses as two pose_soa64
/// streamed by collide_stream; corners (no double stream entry) as one double
/// store holding a then b, decided as the pairs (i, N + i). Each batch's rows are checked
/// apart, so an error names "a: " or "b: " and the row in that batch.
template <class Store, class Row>
std::string collide_stream_doubles(const std::pair<const Row*, std::size_t>& rows_a,
                                   const std::pair<const Row*, std::size_t>& rows_b, const py::array& a,
                                   const py::array& b, obbsat::store_kind kind, py::array& out,
                                   const std::string& method, const std::string& backend, long long threads) {
    const obbsat::collide_options options = options_of(method, backend, threads);
    const std::size_t count = rows_a.second;
    if (count != rows_b.second) {
        throw py::value_error("stream batches differ in length: " + std::to_string(count) + " rows in a, " +
                              std::to_string(rows_b.second) + " in b");
    }
    std::uint8_t* verdicts = verdicts_in_place(out, count);
    require_apart(out, a, "a");
    require_apart(out, b, "b");
    const obbsat::backend ran = without_gil([&] {
        require_runs_on_doubles(options, kind);
        const Store store_a = double_store<Store>(rows_a.first, count, "a");
        const Store store_b = double_store<Store>(rows_b.first, count, "b");
        if constexpr (std::is_same_v<Store, obbsat::pose_soa64>) {
            // Poses have a stream entry of their own: the arrays read as vectors.
            return obbsat::collide_stream(store_a, store_b, verdicts, options);
        } else {
            Store both;
            both.reserve(2 * count);
            for (std::size_t i = 0; i < count; ++i) {
                both.push_back(store_a[i]);
            }
            for (std::size_t i = 0; i < count; ++i) {
                both.push_back(store_b[i]);
            }
            std::vector<obbsat::pair_index> pairs(count);
            for (std::size_t i = 0; i < count; ++i) {
                pairs[i] = obbsat::pair_index{static_cast<std::uint32_t>(i), static_cast<std::uint32_t>(count + i)};
            }
            return obbsat::collide_pairs(both, pairs.data(), count, verdicts, options);
        }
    });
    return obbsat::backend_name(ran);
}

std::string collide_stream64(const py::array& a, const py::array& b, py::array& out, const std::string& method,
                             const std::string& backend, long long threads) {
    return collide_stream_doubles<obbsat::rect_records64>(corners64_in_place(a, "a"), corners64_in_place(b, "b"), a, b,
                                                          obbsat::store_kind::corners, out, method, backend, threads);
}

std::string collide_pose_stream64(const py::array& a, const py::array& b, py::array& out, const std::string& method,
                                  const std::string& backend, long long threads) {
    return collide_stream_doubles<obbsat::pose_soa64>(poses64_in_place(a, "a"), poses64_in_place(b, "b"), a, b,
                                                          obbsat::store_kind::poses, out, method, backend, threads);
}

std::string collide_records(const py::array& rects, const py::array& pairs, py::array& out,
                            const std::string& method, const std::string& backend, long long threads) {
    const obbsat::collide_options options = options_of(method, backend, threads);
    const auto [records, rect_count] = corners_in_place(rects, "rects");
    const auto [pair_list, count] = pairs_in_place(pairs);
    std::uint8_t* verdicts = verdicts_in_place(out, count);
    require_apart(out, rects, "rects");
    require_apart(out, pairs, "pairs");
    const obbsat::backend ran = without_gil([&, records = records, rect_count = rect_count,
                                             pair_list = pair_list, count = count] {
        require_runs_on(options, obbsat::store_kind::corners);
        return obbsat::collide_pairs(records, rect_count, pair_list, count, verdicts, options);
    });
    return obbsat::backend_name(ran);
}

/// A structure-of-arrays copy of a batch; the error names the batch.
obbsat::rect_soa soa_copy(const obbsat::rect* rects, std::size_t count, const char* what) {
    try {
        return obbsat::rect_soa(rects, count);
    } catch (const obbsat::invalid_input& e) {
        throw obbsat::invalid_input(std::string(what) + ": " + e.what());
    }
}

std::string collide_stream(const py::array& a, const py::array& b, py::array& out,
                           const std::string& method, const std::string& backend, long long threads) {
    const obbsat::collide_options options = options_of(method, backend, threads);
    const auto [rects_a, count_a] = corners_in_place(a, "a");
    const auto [rects_b, count_b] = corners_in_place(b, "b");
    if (count_a != count_b) {
        throw py::value_error("stream batches differ in length: " + std::to_string(count_a) +
                              " rectangles in a, " + std::to_string(count_b) + " in b");
    }
    std::uint8_t* verdicts = verdicts_in_place(out, count_a);
    require_apart(out, a, "a");
    require_apart(out, b, "b");
    const obbsat::backend ran = without_gil([&, rects_a = rects_a, rects_b = rects_b,
                                             count_a = count_a, count_b = count_b] {
        require_runs_on(options, obbsat::store_kind::corners);
        const obbsat::rect_soa soa_a = soa_copy(rects_a, count_a, "a");
        const obbsat::rect_soa soa_b = soa_copy(rects_b, count_b, "b");
        return obbsat::collide_stream(soa_a, soa_b, verdicts, options);
    });
    return obbsat::backend_name(ran);
}

std::string collide_poses(const py::array& poses, const py::array& pairs, py::array& out,
                          const std::string& method, const std::string& backend, long long threads) {
    const obbsat::collide_options options = options_of(method, backend, threads);
    const auto [list, pose_count] = poses_in_place(poses, "poses");
    const auto [pair_list, count] = pairs_in_place(pairs);
    std::uint8_t* verdicts = verdicts_in_place(out, count);
    require_apart(out, poses, "poses");
    require_apart(out, pairs, "pairs");
    const obbsat::backend ran = without_gil([&, list = list, pose_count = pose_count, pair_list = pair_list,
                                             count = count] {
        require_runs_on(options, obbsat::store_kind::poses);
        return obbsat::collide_pairs(list, pose_count, pair_list, count, verdicts, options);
    });
    return obbsat::backend_name(ran);
}

/// A pose_soa copy of a batch; the error names the batch.
obbsat::pose_soa pose_soa_copy(const obbsat::rect_pose* poses, std::size_t count, const char* what) {
    try {
        return obbsat::pose_soa(poses, count);
    } catch (const obbsat::invalid_input& e) {
        throw obbsat::invalid_input(std::string(what) + ": " + e.what());
    }
}

std::string collide_pose_stream(const py::array& a, const py::array& b, py::array& out,
                                const std::string& method, const std::string& backend, long long threads) {
    const obbsat::collide_options options = options_of(method, backend, threads);
    const auto [poses_a, count_a] = poses_in_place(a, "a");
    const auto [poses_b, count_b] = poses_in_place(b, "b");
    if (count_a != count_b) {
        throw py::value_error("stream batches differ in length: " + std::to_string(count_a) + " poses in a, " +
                              std::to_string(count_b) + " in b");
    }
    std::uint8_t* verdicts = verdicts_in_place(out, count_a);
    require_apart(out, a, "a");
    require_apart(out, b, "b");
    const obbsat::backend ran = without_gil([&, poses_a = poses_a, poses_b = poses_b, count_a = count_a,
                                             count_b = count_b] {
        require_runs_on(options, obbsat::store_kind::poses);
        const obbsat::pose_soa soa_a = pose_soa_copy(poses_a, count_a, "a");
        const obbsat::pose_soa soa_b = pose_soa_copy(poses_b, count_b, "b");
        return obbsat::collide_stream(soa_a, soa_b, verdicts, options);
    });
    return obbsat::backend_name(ran);
}

/// The corner rows of `out`: float32, C-contiguous, writable, shape (count, 4, 2).
obbsat::rect* corners_out(py::array& out, std::size_t count) {
    if (out.ndim() != 3 || out.shape(1) != 4 || out.shape(2) != 2 || !holds<float>(out) || !is_c_contiguous(out) ||
        !out.writeable() || static_cast<std::size_t>(out.shape(0)) != count) {
        throw py::type_error("out: expected a writable, C-contiguous float32 array of shape (" +
                             std::to_string(count) + ", 4, 2)");
    }
    return static_cast<obbsat::rect*>(out.mutable_data());
}

std::string store_corners(const obbsat::pose_records& store, py::array& out, const std::string& backend) {
    const obbsat::backend requested = backend_named(backend);
    obbsat::rect* corners = corners_out(out, store.size());
    const obbsat::backend ran = without_gil([&] { return obbsat::convert_to_corners(store, corners, requested); });
    return obbsat::backend_name(ran);
}

std::string pose_corners(const py::array& poses, py::array& out, const std::string& backend) {
    const obbsat::backend requested = backend_named(backend);
    const auto [list, count] = poses_in_place(poses, "poses");
    obbsat::rect* corners = corners_out(out, count);
    require_apart(out, poses, "poses");
    const obbsat::backend ran = without_gil([&, list = list, count = count] {
        const obbsat::backend resolved = obbsat::resolve_backend(requested);
        const obbsat::pose_records store(list, count);
        return obbsat::convert_to_corners(store, corners, resolved);
    });
    return obbsat::backend_name(ran);
}

// --- Scene queries ---------------------------------------------------------

/// One side of a scene query: a store passed from Python, or the rows of an
/// array (read in place and checked by the query). The Python objects
/// outlive the call, so both pointers stay valid.
template <class Store>
struct scene_side {
    const Store* store = nullptr;
    const typename store_traits<Store>::row* rows = nullptr;
    std::size_t count = 0;
    const char* what = "";
};

template <class Store>
scene_side<Store> side_of(const py::handle& boxes, const char* what) {
    using traits = store_traits<Store>;
    scene_side<Store> side;
    side.what = what;
    if (py::isinstance<Store>(boxes)) {
        side.store = &boxes.cast<const Store&>();
        return side;
    }
    if (!py::isinstance<py::array>(boxes)) {
        throw py::type_error(std::string(what) + ": expected a numpy array or a " + traits::class_name + ", got " +
                             std::string(py::str(py::type::of(boxes).attr("__name__"))));
    }
    const auto [rows, count] = traits::rows_in_place(py::reinterpret_borrow<py::array>(boxes), what);
    side.rows = rows;
    side.count = count;
    return side;
}

/// What the scene query reads of `side`: the store, or the rows in place.
template <class Store>
obbsat::box_view view_of(const scene_side<Store>& side) {
    if (side.store != nullptr) {
        return obbsat::box_view(*side.store);
    }
    return obbsat::box_view(side.rows, side.count);
}

/// The rows of one side of a scene query.
template <class Store>
std::size_t rows_of(const scene_side<Store>& side) {
    return side.store != nullptr ? side.store->size() : side.count;
}

/// A filter array of `what` as the library reads it: an array of T (uint64
/// for categories and masks, int32 for groups), one value per row; None
/// stays None (not given). Any integer dtype is taken when every
/// value fits in T; the result is `given` itself when it is already T and
/// contiguous, so it is read in place.
template <class T>
py::object filter_array(const py::object& given, const std::string& name, std::size_t rows, const char* side) {
    using converted = py::array_t<T, py::array::c_style | py::array::forcecast>;
    if (given.is_none()) {
        return py::none();
    }
    py::array a = py::array::ensure(given);
    if (!a) {
        throw py::type_error(name + ": expected an array of integers");
    }
    const char kind = a.dtype().kind();
    if (kind != 'i' && kind != 'u') {
        throw py::type_error(name + ": expected integers, got dtype " + std::string(py::str(a.dtype())));
    }
    if (a.ndim() != 1) {
        throw py::value_error(name + ": expected one value per row (a 1-D array), got " + std::to_string(a.ndim()) +
                              " dimensions");
    }
    if (static_cast<std::size_t>(a.shape(0)) != rows) {
        throw py::value_error(name + ": " + std::to_string(a.shape(0)) + " values for the " + std::to_string(rows) +
                              " rows of " + side);
    }
    // Read as the widest type of its sign (no loss), then checked against T's range.
    constexpr auto lowest = static_cast<long long>(std::numeric_limits<T>::min());
    constexpr auto highest = std::numeric_limits<T>::max();
    if (kind == 'u') {
        const auto wide = py::array_t<std::uint64_t, py::array::c_style | py::array::forcecast>::ensure(a);
        const std::uint64_t* v = wide.data();
        for (std::size_t i = 0; i < rows; ++i) {
            if (v[i] > static_cast<std::uint64_t>(highest)) {
                throw py::value_error(name + "[" + std::to_string(i) + "] = " + std::to_string(v[i]) +
                                      " does not fit in " + (sizeof(T) == 4 ? "int32" : "uint64"));
            }
        }
    } else {
        const auto wide = py::array_t<std::int64_t, py::array::c_style | py::array::forcecast>::ensure(a);
        const std::int64_t* v = wide.data();
        for (std::size_t i = 0; i < rows; ++i) {
            if (v[i] < lowest || (v[i] > 0 && static_cast<std::uint64_t>(v[i]) > static_cast<std::uint64_t>(highest))) {
                throw py::value_error(name + "[" + std::to_string(i) + "] = " + std::to_string(v[i]) +
                                      (lowest == 0 ? " is negative: categories and masks are bit sets"
                                                   : " does not fit in int32"));
            }
        }
    }
    return converted::ensure(a);
}

/// The pair filters of one side: the arrays, kept alive for the query, and
/// the library's view of them.
struct side_filters {
    py::object categories = py::none(), masks = py::none(), groups = py::none();

    obbsat::pair_filters view() const {
        obbsat::pair_filters f;
        f.categories = values_of<std::uint64_t>(categories);
        f.masks = values_of<std::uint64_t>(masks);
        f.groups = values_of<std::int32_t>(groups);
        return f;
    }

private:
    /// The values of an array of filter_array, nullptr for None.
    template <class T>
    static const T* values_of(const py::object& given) {
        return given.is_none() ? nullptr : static_cast<const T*>(py::reinterpret_borrow<py::array>(given).data());
    }
};

/// The filters a scene query was given from Python, for `boxes` and for
/// `against` (whose arrays are named against_categories, ...).
struct filter_args {
    py::object categories, masks, groups, against_categories, against_masks, against_groups;
};

template <class Store>
side_filters filters_of(const scene_side<Store>& side, const py::object& categories, const py::object& masks,
                        const py::object& groups, const std::string& prefix) {
    const std::size_t rows = rows_of(side);
    side_filters f;
    f.categories = filter_array<std::uint64_t>(categories, prefix + "categories", rows, side.what);
    f.masks = filter_array<std::uint64_t>(masks, prefix + "masks", rows, side.what);
    f.groups = filter_array<std::int32_t>(groups, prefix + "groups", rows, side.what);
    return f;
}

/// The filters of both sides; those of `against` must come with it.
template <class Store>
std::pair<side_filters, side_filters> filters_of(const filter_args& args, const scene_side<Store>& a,
                                                 const scene_side<Store>* b) {
    if (b == nullptr) {
        for (const auto& [value, name] : {std::make_pair(&args.against_categories, "against_categories"),
                                          std::make_pair(&args.against_masks, "against_masks"),
                                          std::make_pair(&args.against_groups, "against_groups")}) {
            if (!value->is_none()) {
                throw py::value_error(std::string(name) + " given without against");
            }
        }
        return {filters_of(a, args.categories, args.masks, args.groups, ""), side_filters{}};
    }
    return {filters_of(a, args.categories, args.masks, args.groups, ""),
            filters_of(*b, args.against_categories, args.against_masks, args.against_groups, "against_")};
}

/// Runs `query`; a bad row of a cross query, which the library names "a: ..."
/// or "b: ...", is named "boxes: ..." or "against: ..." as Python calls them.
template <class Query>
auto with_side_names(const Query& query) {
    try {
        return query();
    } catch (const obbsat::invalid_input& e) {
        const std::string text = e.what();
        if (text.rfind("a: ", 0) == 0) {
            throw obbsat::invalid_input("boxes: " + text.substr(3));
        }
        if (text.rfind("b: ", 0) == 0) {
            throw obbsat::invalid_input("against: " + text.substr(3));
        }
        throw;
    }
}

/// The pairs as a uint32 (K, 2) array that owns `pairs`' memory (no copy).
py::array_t<std::uint32_t> pair_array(std::vector<obbsat::pair_index>&& pairs) {
    const py::ssize_t count = static_cast<py::ssize_t>(pairs.size());
    if (pairs.empty()) {
        return py::array_t<std::uint32_t>({count, py::ssize_t{2}});
    }
    auto owned = std::make_unique<std::vector<obbsat::pair_index>>(std::move(pairs));
    const auto* data = reinterpret_cast<const std::uint32_t*>(owned->data());
    py::capsule owner(owned.get(), [](void* p) { delete static_cast<std::vector<obbsat::pair_index>*>(p); });
    owned.release();
    return py::array_t<std::uint32_t>({count, py::ssize_t{2}}, data, owner);
}

/// Every colliding pair of `boxes` (against = None) or across `boxes` and
/// `against`, both of the store kind Store, sorted.
template <class Store>
py::array_t<std::uint32_t> find_pairs_of(const py::object& boxes, const py::object& against,
                                         const std::string& method, const std::string& backend, long long threads,
                                         const py::object& categories, const py::object& masks,
                                         const py::object& groups, const py::object& against_categories,
                                         const py::object& against_masks, const py::object& against_groups) {
    const obbsat::collide_options options = options_of(method, backend, threads);
    const bool cross = !against.is_none();
    const scene_side<Store> a = side_of<Store>(boxes, "boxes");
    const scene_side<Store> b = cross ? side_of<Store>(against, "against") : scene_side<Store>{};
    const std::pair<side_filters, side_filters> filters = filters_of(
        filter_args{categories, masks, groups, against_categories, against_masks, against_groups}, a,
        cross ? &b : nullptr);
    const obbsat::pair_filters fa = filters.first.view();
    const obbsat::pair_filters fb = filters.second.view();
    return pair_array(without_gil([&] {
        store_traits<Store>::require_method(options);
        const obbsat::box_view va = view_of(a).with_filters(fa);
        return with_side_names([&] {
            return cross ? obbsat::find_pairs(va, view_of(b).with_filters(fb), options)
                         : obbsat::find_pairs(va, options);
        });
    }));
}

/// The ids of one side of a PairFinder query (the package converted them to
/// uint64 and checked their sign): a C-contiguous uint64 vector of one id per
/// row, read in place; None for no ids.
struct side_ids {
    const std::uint64_t* ids = nullptr;
    std::size_t count = 0;
    bool given = false;
};

side_ids ids_of(const py::object& ids, std::size_t rows, const char* what) {
    side_ids out;
    if (ids.is_none()) {
        return out;
    }
    const py::array a = py::reinterpret_borrow<py::array>(ids);
    if (!py::isinstance<py::array>(ids) || a.ndim() != 1 || !holds<std::uint64_t>(a) || !is_c_contiguous(a)) {
        throw py::type_error(std::string(what) + ": expected a C-contiguous uint64 array of shape (N,)");
    }
    if (static_cast<std::size_t>(a.shape(0)) != rows) {
        throw py::value_error(std::string(what) + ": " + std::to_string(a.shape(0)) + " ids for " +
                              std::to_string(rows) + " rows; give one id per row");
    }
    out.ids = static_cast<const std::uint64_t*>(a.data());
    out.count = rows;
    out.given = true;
    return out;
}

/// `view` with `ids` when they were given.
obbsat::box_view with_ids_of(const obbsat::box_view& view, const side_ids& ids) {
    return ids.given ? view.with_ids(ids.ids, ids.count) : view;
}

/// Id pairs as a uint64 (K, 2) array (a copy).
py::array_t<std::uint64_t> id_pair_array(const std::vector<obbsat::id_pair>& pairs) {
    static_assert(sizeof(obbsat::id_pair) == 2 * sizeof(std::uint64_t), "an id pair is two uint64");
    py::array_t<std::uint64_t> out({static_cast<py::ssize_t>(pairs.size()), py::ssize_t{2}});
    if (!pairs.empty()) {
        std::memcpy(out.mutable_data(), pairs.data(), pairs.size() * sizeof(obbsat::id_pair));
    }
    return out;
}

/// A pair_finder shared with Python: one query at a time (a second thread
/// waits, without the GIL), each answer copied out of the finder's buffer,
/// which the next query reuses.
class scene_finder {
public:
    explicit scene_finder(const obbsat::collide_options& options) : options_(options), finder_(options) {}

    template <class Store>
    py::array_t<std::uint32_t> find(const py::object& boxes, const py::object& against, const py::object& ids,
                                    const py::object& against_ids, const py::object& categories,
                                    const py::object& masks, const py::object& groups,
                                    const py::object& against_categories, const py::object& against_masks,
                                    const py::object& against_groups) {
        return pair_array(query<Store>(boxes, against, ids, against_ids, categories, masks, groups,
                                       against_categories, against_masks, against_groups,
                                       [&](const obbsat::box_view& a, const obbsat::box_view* b) {
                                           return std::vector<obbsat::pair_index>(b ? finder_.find(a, *b)
                                                                                    : finder_.find(a));
                                       }));
    }

    /// find, with the contact of each pair (obbsat::pair_finder::find_contacts,
    /// or find_contacts64 on a double store's rows: float64 columns): (pairs, contact columns).
    template <class Store>
    py::tuple find_contacts(const py::object& boxes, const py::object& against, const py::object& ids,
                            const py::object& against_ids, const py::object& categories, const py::object& masks,
                            const py::object& groups, const py::object& against_categories,
                            const py::object& against_masks, const py::object& against_groups) {
        constexpr bool doubles = std::is_same<typename store_traits<Store>::value, double>::value;
        using contact_type = std::conditional_t<doubles, obbsat::contact64, obbsat::contact>;
        // The frame's contacts stay in the finder until its next call, which
        // waits for the mutex; the columns are copied out before.
        std::vector<contact_type> contacts;
        std::vector<obbsat::pair_index> pairs = query<Store>(
            boxes, against, ids, against_ids, categories, masks, groups, against_categories, against_masks,
            against_groups, [&](const obbsat::box_view& a, const obbsat::box_view* b) {
                if constexpr (doubles) {
                    const obbsat::scene_contacts64& found =
                        b ? finder_.find_contacts64(a, *b) : finder_.find_contacts64(a);
                    contacts = found.contacts;
                    return found.pairs;
                } else {
                    const obbsat::scene_contacts& found = b ? finder_.find_contacts(a, *b) : finder_.find_contacts(a);
                    contacts = found.contacts;
                    return found.pairs;
                }
            });
        py::dict columns = contact_dict(contacts.data(), contacts.size());
        return py::make_tuple(pair_array(std::move(pairs)), columns);
    }

private:
    /// Runs `call(a, b)` (b nullptr within one set) on the rows, filters and
    /// ids given, with the finder's lock held and the GIL released.
    template <class Store, class Call>
    std::vector<obbsat::pair_index> query(const py::object& boxes, const py::object& against, const py::object& ids,
                                          const py::object& against_ids, const py::object& categories,
                                          const py::object& masks, const py::object& groups,
                                          const py::object& against_categories, const py::object& against_masks,
                                          const py::object& against_groups, const Call& call) {
        const bool cross = !against.is_none();
        const scene_side<Store> a = side_of<Store>(boxes, "boxes");
        const scene_side<Store> b = cross ? side_of<Store>(against, "against") : scene_side<Store>{};
        const std::pair<side_filters, side_filters> filters = filters_of(
            filter_args{categories, masks, groups, against_categories, against_masks, against_groups}, a,
            cross ? &b : nullptr);
        const obbsat::pair_filters fa = filters.first.view();
        const obbsat::pair_filters fb = filters.second.view();
        const side_ids a_ids = ids_of(ids, view_of(a).size(), "ids");
        const side_ids b_ids = cross ? ids_of(against_ids, view_of(b).size(), "against_ids") : side_ids{};
        if (cross && a_ids.given != b_ids.given) {
            throw py::value_error(std::string(a_ids.given ? "ids" : "against_ids") + " given without " +
                                  (a_ids.given ? "against_ids" : "ids") +
                                  ": a query across two sets takes ids for both or for neither");
        }
        return without_gil([&] {
            const std::lock_guard<std::mutex> lock(mutex_);
            store_traits<Store>::require_method(options_);
            const obbsat::box_view va = with_ids_of(view_of(a).with_filters(fa), a_ids);
            return with_side_names([&] {
                std::vector<obbsat::pair_index> found;
                if (cross) {
                    const obbsat::box_view vb = with_ids_of(view_of(b).with_filters(fb), b_ids);
                    found = call(va, &vb);
                } else {
                    found = call(va, nullptr);
                }
                last_with_ids_ = a_ids.given;
                return found;
            });
        });
    }

public:

    obbsat::find_pairs_stats stats() {
        py::gil_scoped_release release;
        const std::lock_guard<std::mutex> lock(mutex_);
        return finder_.stats();
    }

    /// Turns the finder's begin/end events on or off (obbsat::pair_finder::track_events).
    void track_events(bool on) {
        py::gil_scoped_release release;
        const std::lock_guard<std::mutex> lock(mutex_);
        finder_.track_events(on);
    }

    /// A copy of the pairs that began (or ended) at the last query: row
    /// pairs, uint32 (K, 2); id pairs, uint64 (K, 2), when its rows had ids.
    py::object events(bool began) {
        bool by_id = false;
        std::vector<obbsat::pair_index> rows;
        std::vector<obbsat::id_pair> ids;
        without_gil([&] {
            const std::lock_guard<std::mutex> lock(mutex_);
            by_id = last_with_ids_;
            if (by_id) {
                ids = began ? finder_.began_ids() : finder_.ended_ids();
            } else {
                rows = began ? finder_.began() : finder_.ended();
            }
            return 0;
        });
        if (by_id) {
            return id_pair_array(ids);
        }
        return pair_array(std::move(rows));
    }

private:
    obbsat::collide_options options_;
    std::mutex mutex_;
    obbsat::pair_finder finder_;
    bool last_with_ids_ = false;  ///< the last query that answered had ids
};

std::unique_ptr<scene_finder> make_scene_finder(const std::string& method, const std::string& backend,
                                                long long threads) {
    const obbsat::collide_options options = options_of(method, backend, threads);
    // A backend this CPU cannot run is refused here rather than at the first query.
    obbsat::resolve_backend(options.use);
    return std::make_unique<scene_finder>(options);
}

/// The rectangles of a corner array are finite, or the library's message names the first that is not.
void require_finite_corners(const obbsat::rect* rects, std::size_t count) {
    for (std::size_t i = 0; i < count; ++i) {
        const float* v = &rects[i].ul.x;
        for (int k = 0; k < 8; ++k) {
            if (!std::isfinite(v[k])) {
                obbsat::rect_records{rects, i + 1};  // throws, naming rectangle i and its coordinate
            }
        }
    }
}

/// Writes the bounds of `count` boxes, each read by `box(i)`, as rows lo_x, lo_y, hi_x, hi_y.
template <class Box>
void write_bounds(std::size_t count, const Box& box, float* out) {
    for (std::size_t i = 0; i < count; ++i) {
        const obbsat::ref::box_bounds b = obbsat::ref::bounds_of(box(i));
        out[4 * i + 0] = b.lo_x;
        out[4 * i + 1] = b.lo_y;
        out[4 * i + 2] = b.hi_x;
        out[4 * i + 3] = b.hi_y;
    }
}

/// The bounds of every box of a store of kind Store, or of an array of its
/// rows (checked as the store checks them), as float32 (N, 4).
template <class Store>
py::array_t<float> bounds_of(const py::object& boxes) {
    const scene_side<Store> side = side_of<Store>(boxes, "boxes");
    const std::size_t count = side.store != nullptr ? side.store->size() : side.count;
    py::array_t<float> out({static_cast<py::ssize_t>(count), py::ssize_t{4}});
    float* rows = out.mutable_data();
    without_gil([&] {
        if (side.store != nullptr) {
            const Store& store = *side.store;
            write_bounds(count, [&](std::size_t i) { return store[i]; }, rows);
        } else if constexpr (std::is_same<Store, obbsat::rect_records>::value) {
            require_finite_corners(side.rows, count);
            write_bounds(count, [&](std::size_t i) { return side.rows[i]; }, rows);
        } else if constexpr (std::is_same<Store, obbsat::rect_records64>::value) {
            for (std::size_t i = 0; i < count; ++i) {
                obbsat::require_finite(side.rows[i], i);
            }
            write_bounds(count, [&](std::size_t i) { return side.rows[i]; }, rows);
        } else {
            for (std::size_t i = 0; i < count; ++i) {
                obbsat::require_valid_pose(side.rows[i], i);
            }
            write_bounds(count, [&](std::size_t i) { return side.rows[i]; }, rows);
        }
        return true;
    });
    return out;
}

py::array_t<float> make_pose_scene(std::size_t boxes, const std::string& sizes, double pairs_per_box,
                                   std::uint64_t seed) {
    const std::optional<obbsat::scene_sizes> parsed = obbsat::parse_scene_sizes(sizes);
    if (!parsed) {
        throw py::value_error("unknown sizes '" + sizes + "' (known: uniform, mixed)");
    }
    obbsat::pose_scene_spec spec;
    spec.seed = seed;
    spec.boxes = boxes;
    spec.sizes = *parsed;
    spec.pairs_per_box = pairs_per_box;
    std::vector<obbsat::rect_pose> poses;
    {
        py::gil_scoped_release release;
        poses = obbsat::make_pose_scene(spec);
    }
    py::array_t<float> out({static_cast<py::ssize_t>(poses.size()), py::ssize_t{6}});
    if (!poses.empty()) {
        std::memcpy(out.mutable_data(), poses.data(), poses.size() * sizeof(obbsat::rect_pose));
    }
    return out;
}

std::vector<std::string> runnable_backends() {
    std::vector<std::string> names;
    for (const obbsat::backend b : obbsat::compiled_backends()) {
        if (obbsat::cpu_supports(b)) {
            names.emplace_back(obbsat::backend_name(b));
        }
    }
    return names;
}

std::vector<std::string> compiled_backend_names() {
    std::vector<std::string> names;
    for (const obbsat::backend b : obbsat::compiled_backends()) {
        names.emplace_back(obbsat::backend_name(b));
    }
    return names;
}

std::vector<std::string> method_names(const std::string& store) {
    obbsat::store_kind kind;
    if (store == obbsat::store_name(obbsat::store_kind::corners)) {
        kind = obbsat::store_kind::corners;
    } else if (store == obbsat::store_name(obbsat::store_kind::poses)) {
        kind = obbsat::store_kind::poses;
    } else {
        throw py::value_error("unknown store '" + store + "' (known: corners, poses)");
    }
    std::vector<std::string> names;
    for (const obbsat::method m : obbsat::methods_on(kind)) {
        names.emplace_back(obbsat::method_name(m));
    }
    return names;
}

std::string resolved_backend(const std::string& name) {
    const obbsat::backend requested = backend_named(name);
    return obbsat::backend_name(obbsat::resolve_backend(requested));
}

py::tuple make_scene(std::size_t rects, std::size_t pairs, const std::string& density, std::uint64_t seed) {
    obbsat::scene_density d;
    if (density == "sparse") {
        d = obbsat::scene_density::sparse;
    } else if (density == "typical") {
        d = obbsat::scene_density::typical;
    } else if (density == "dense") {
        d = obbsat::scene_density::dense;
    } else {
        throw py::value_error("unknown density '" + density + "' (known: sparse, typical, dense)");
    }
    obbsat::scene s;
    {
        py::gil_scoped_release release;
        s = obbsat::make_scene(obbsat::scene_spec_for(d, rects, pairs, seed));
    }
    const std::size_t n = s.rects.size();
    py::array_t<float> corners({static_cast<py::ssize_t>(n), py::ssize_t{8}});
    float* c = corners.mutable_data();
    for (std::size_t i = 0; i < n; ++i) {
        const obbsat::rect r = s.rects[i];
        std::memcpy(c + 8 * i, &r, sizeof r);
    }
    py::array_t<std::uint32_t> pair_array({static_cast<py::ssize_t>(s.pairs.size()), py::ssize_t{2}});
    if (!s.pairs.empty()) {
        std::memcpy(pair_array.mutable_data(), s.pairs.data(), s.pairs.size() * sizeof(obbsat::pair_index));
    }
    return py::make_tuple(corners, pair_array);
}

}  // namespace

PYBIND11_MODULE(_core, m) {
    m.doc() = "obbsat's compiled entry points; use the obbsat package, which checks and converts arguments.";
    py::register_exception<obbsat::unsupported_backend>(m, "UnsupportedBackendError", PyExc_ValueError);
    register_contacts(m);

    m.def("collide_records", &collide_records, py::arg("rects"), py::arg("pairs"), py::arg("out"),
          py::arg("method"), py::arg("backend"), py::arg("threads"),
          "Verdicts of pairs over rectangles read in place (float32 (N, 8), uint32 (M, 2), out uint8/bool (M,)); "
          "returns the backend that ran.");
    def_store<obbsat::rect_records>(
        m, "Rectangles as packed 32-byte records of float32 corners, copied and checked once.",
        "A checked copy of float32 (N, 8) corners (ValueError naming a non-finite coordinate).",
        "The records as a read-only float32 (N, 8) array over the store's own memory.");
    def_store<obbsat::pose_records>(
        m, "Poses as the library's 32-byte records of float32, copied and checked once.",
        "A checked copy of float32 (N, 6) poses (ValueError naming the first bad pose and field).",
        "The poses as a read-only float32 (N, 6) view of the store's own records (rows 32 bytes apart).");
    def_store<obbsat::rect_records64>(
        m, "Rectangles as 64-byte records of float64 corners (rect_records64), every double kept exactly, "
           "copied and checked once.",
        "A checked copy of float64 (N, 8) corners (ValueError naming a non-finite coordinate).",
        "The records as a read-only float64 (N, 8) array over the store's own memory.");
    def_store<obbsat::pose_records64>(
        m, "Poses as 64-byte records of float64 (pose_records64), every double kept exactly, copied and "
           "checked once.",
        "A checked copy of float64 (N, 6) poses (ValueError naming the first bad pose and field).",
        "The poses as a read-only float64 (N, 6) view of the store's own records (rows 64 bytes apart).");
    m.def("collide_store", &collide_store<obbsat::rect_records>, py::arg("store"), py::arg("pairs"), py::arg("out"),
          py::arg("method"), py::arg("backend"), py::arg("threads"),
          "Verdicts of pairs over a RectRecords store; returns the backend that ran.");
    m.def("collide_store64", &collide_store<obbsat::rect_records64>, py::arg("store"), py::arg("pairs"),
          py::arg("out"), py::arg("method"), py::arg("backend"), py::arg("threads"),
          "Verdicts of pairs over a RectRecords64 store (as collide_records64 over its rows); "
          "returns the backend that ran.");
    m.def("collide_stream", &collide_stream, py::arg("a"), py::arg("b"), py::arg("out"), py::arg("method"),
          py::arg("backend"), py::arg("threads"),
          "Verdicts of a[i] against b[i] (float32 (N, 8) each, copied to the structure-of-arrays store); "
          "returns the backend that ran.");
    m.def("collide_stream64", &collide_stream64, py::arg("a"), py::arg("b"), py::arg("out"), py::arg("method"),
          py::arg("backend"), py::arg("threads"),
          "Verdicts of a[i] against b[i] over float64 corners (N, 8) (copied once into one double store); "
          "returns the backend that ran.");
    m.def("collide_pose_stream64", &collide_pose_stream64, py::arg("a"), py::arg("b"), py::arg("out"),
          py::arg("method"), py::arg("backend"), py::arg("threads"),
          "Verdicts of a[i] against b[i] over float64 poses (N, 6) (copied once into one double store); "
          "returns the backend that ran.");
    m.def("collide_records64", &collide_records64, py::arg("rects"), py::arg("pairs"), py::arg("out"),
          py::arg("method"), py::arg("backend"), py::arg("threads"),
          "Verdicts of pairs over float64 corners (N, 8) (copied once into a rect_records64 store); "
          "returns the backend that ran.");
    m.def("collide_poses64", &collide_poses64, py::arg("poses"), py::arg("pairs"), py::arg("out"),
          py::arg("method"), py::arg("backend"), py::arg("threads"),
          "Verdicts of pairs over float64 poses (N, 6) (copied once into a pose_records64 store); "
          "returns the backend that ran.");
    m.def("collide_poses", &collide_poses, py::arg("poses"), py::arg("pairs"), py::arg("out"), py::arg("method"),
          py::arg("backend"), py::arg("threads"),
          "Verdicts of pairs over poses (float32 (N, 6), copied once into 32-byte records); "
          "returns the backend that ran.");
    m.def("collide_pose_store", &collide_store<obbsat::pose_records>, py::arg("store"), py::arg("pairs"),
          py::arg("out"), py::arg("method"), py::arg("backend"), py::arg("threads"),
          "Verdicts of pairs over a PoseRecords store; returns the backend that ran.");
    m.def("collide_pose_store64", &collide_store<obbsat::pose_records64>, py::arg("store"), py::arg("pairs"),
          py::arg("out"), py::arg("method"), py::arg("backend"), py::arg("threads"),
          "Verdicts of pairs over a PoseRecords64 store (as collide_poses64 over its rows); "
          "returns the backend that ran.");
    m.def("collide_pose_stream", &collide_pose_stream, py::arg("a"), py::arg("b"), py::arg("out"),
          py::arg("method"), py::arg("backend"), py::arg("threads"),
          "Verdicts of a[i] against b[i] (float32 (N, 6) each, copied to pose_soa stores); "
          "returns the backend that ran.");
    m.def("pose_corners", &pose_corners, py::arg("poses"), py::arg("out"), py::arg("backend"),
          "The corners of float32 (N, 6) poses written to out, float32 (N, 4, 2); returns the backend that ran.");
    m.def("store_corners", &store_corners, py::arg("store"), py::arg("out"), py::arg("backend"),
          "The corners of a PoseRecords store written to out, float32 (N, 4, 2); returns the backend that ran.");
    m.def("find_pairs_corners", &find_pairs_of<obbsat::rect_records>, py::arg("boxes"), py::arg("against"),
          py::arg("method"), py::arg("backend"), py::arg("threads"),
          py::arg("categories") = py::none(), py::arg("masks") = py::none(), py::arg("groups") = py::none(),
          py::arg("against_categories") = py::none(), py::arg("against_masks") = py::none(),
          py::arg("against_groups") = py::none(),
          "Every colliding pair of corner boxes (float32 (N, 8) or (N, 4, 2), copied into records, or a "
          "RectRecords), or across boxes and against: uint32 (K, 2) sorted by (i, j).");
    m.def("find_pairs_poses", &find_pairs_of<obbsat::pose_records>, py::arg("boxes"), py::arg("against"),
          py::arg("method"), py::arg("backend"), py::arg("threads"),
          py::arg("categories") = py::none(), py::arg("masks") = py::none(), py::arg("groups") = py::none(),
          py::arg("against_categories") = py::none(), py::arg("against_masks") = py::none(),
          py::arg("against_groups") = py::none(),
          "Every colliding pair of poses (float32 (N, 6), copied into records, or a PoseRecords), or across "
          "boxes and against: uint32 (K, 2) sorted by (i, j).");
    m.def("find_pairs_corners64", &find_pairs_of<obbsat::rect_records64>, py::arg("boxes"), py::arg("against"),
          py::arg("method"), py::arg("backend"), py::arg("threads"),
          py::arg("categories") = py::none(), py::arg("masks") = py::none(), py::arg("groups") = py::none(),
          py::arg("against_categories") = py::none(), py::arg("against_masks") = py::none(),
          py::arg("against_groups") = py::none(),
          "Every colliding pair of float64 corner boxes ((N, 8) or (N, 4, 2), read in place, or a RectRecords64; "
          "every double taken exactly), or across boxes and against: uint32 (K, 2) sorted by (i, j).");
    m.def("find_pairs_poses64", &find_pairs_of<obbsat::pose_records64>, py::arg("boxes"), py::arg("against"),
          py::arg("method"), py::arg("backend"), py::arg("threads"),
          py::arg("categories") = py::none(), py::arg("masks") = py::none(), py::arg("groups") = py::none(),
          py::arg("against_categories") = py::none(), py::arg("against_masks") = py::none(),
          py::arg("against_groups") = py::none(),
          "Every colliding pair of float64 poses ((N, 6), read in place, or a PoseRecords64; every double taken "
          "exactly), or across "
          "boxes and against: uint32 (K, 2) sorted by (i, j).");
    py::class_<obbsat::find_pairs_stats>(m, "FindPairsStats", "What one scene query did (obbsat::find_pairs_stats).")
        .def(py::init<>())
        .def_readonly("boxes", &obbsat::find_pairs_stats::boxes,
                      "rectangles in the query (both sides of a cross query)")
        .def_readonly("strips", &obbsat::find_pairs_stats::strips, "horizontal strips of the sweep")
        .def_readonly("visits", &obbsat::find_pairs_stats::visits,
                      "extra strip entries of rectangles taller than their strip")
        .def_readonly("candidates", &obbsat::find_pairs_stats::candidates,
                      "pairs handed to the method: those whose bounds overlap (a finder with method exact, from kept candidates: every kept one)")
        .def_readonly("pairs", &obbsat::find_pairs_stats::pairs, "pairs reported")
        .def_readonly("slow_path_pairs", &obbsat::find_pairs_stats::slow_path_pairs,
                      "candidates decided on the exact slow path (method exact)")
        .def_readonly("reused_order", &obbsat::find_pairs_stats::reused_order,
                      "the previous query's order was repaired, not rebuilt")
        .def_readonly("reused_candidates", &obbsat::find_pairs_stats::reused_candidates,
                      "PairFinder: answered from the candidates the last full query kept, without a sweep")
        .def_readonly("kept_candidates", &obbsat::find_pairs_stats::kept_candidates,
                      "PairFinder: candidates of the widened bounds kept for the next calls")
        .def_readonly("bounds_seconds", &obbsat::find_pairs_stats::bounds_seconds,
                      "bounds, the strips and the sort keys")
        .def_readonly("order_seconds", &obbsat::find_pairs_stats::order_seconds,
                      "sorting, copying the records into the sorted order, visits")
        .def_readonly("sweep_seconds", &obbsat::find_pairs_stats::sweep_seconds,
                      "broadphase sweep and the method's kernels")
        .def_readonly("kernel_seconds", &obbsat::find_pairs_stats::kernel_seconds,
                      "the method's kernels alone, summed over the threads (part of the sweep)")
        .def_readonly("output_seconds", &obbsat::find_pairs_stats::output_seconds,
                      "mapping back to the caller's indices and sorting")
        .def("__repr__", [](const obbsat::find_pairs_stats& s) {
            const auto count = [](const char* name, std::size_t value) {
                return std::string(name) + "=" + std::to_string(value) + ", ";
            };
            const auto seconds = [](const char* name, double value) {
                return std::string(name) + "=" + std::string(py::repr(py::float_(value)));
            };
            return "FindPairsStats(" + count("boxes", s.boxes) + count("strips", s.strips) +
                   count("visits", s.visits) + count("candidates", s.candidates) + count("pairs", s.pairs) +
                   count("slow_path_pairs", s.slow_path_pairs) + "reused_order=" +
                   (s.reused_order ? "True, " : "False, ") + "reused_candidates=" +
                   (s.reused_candidates ? "True, " : "False, ") + count("kept_candidates", s.kept_candidates) +
                   seconds("bounds_seconds", s.bounds_seconds) + ", " +
                   seconds("order_seconds", s.order_seconds) + ", " + seconds("sweep_seconds", s.sweep_seconds) +
                   ", " + seconds("kernel_seconds", s.kernel_seconds) + ", " +
                   seconds("output_seconds", s.output_seconds) + ")";
        });
    py::class_<scene_finder>(m, "PairFinder",
                             "obbsat::pair_finder: a scene query that keeps its order and buffers between calls.")
        .def(py::init(&make_scene_finder), py::arg("method"), py::arg("backend"), py::arg("threads"))
        .def("find_corners", &scene_finder::find<obbsat::rect_records>, py::arg("boxes"), py::arg("against"),
             py::arg("ids"), py::arg("against_ids"),
             py::arg("categories") = py::none(), py::arg("masks") = py::none(), py::arg("groups") = py::none(),
             py::arg("against_categories") = py::none(), py::arg("against_masks") = py::none(),
             py::arg("against_groups") = py::none(),
             "find_pairs_corners through the finder, rows matched by id when ids (uint64 (N,)) are given; the "
             "pairs are a copy of its buffer.")
        .def("find_poses", &scene_finder::find<obbsat::pose_records>, py::arg("boxes"), py::arg("against"),
             py::arg("ids"), py::arg("against_ids"),
             py::arg("categories") = py::none(), py::arg("masks") = py::none(), py::arg("groups") = py::none(),
             py::arg("against_categories") = py::none(), py::arg("against_masks") = py::none(),
             py::arg("against_groups") = py::none(),
             "find_pairs_poses through the finder, rows matched by id when ids (uint64 (N,)) are given; the "
             "pairs are a copy of its buffer.")
        .def("find_contacts_corners", &scene_finder::find_contacts<obbsat::rect_records>, py::arg("boxes"),
             py::arg("against"), py::arg("ids"), py::arg("against_ids"), py::arg("categories") = py::none(),
             py::arg("masks") = py::none(), py::arg("groups") = py::none(),
             py::arg("against_categories") = py::none(), py::arg("against_masks") = py::none(),
             py::arg("against_groups") = py::none(),
             "find_corners with the contact of each pair (obbsat::pair_finder::find_contacts): (pairs, columns).")
        .def("find_contacts_poses", &scene_finder::find_contacts<obbsat::pose_records>, py::arg("boxes"),
             py::arg("against"), py::arg("ids"), py::arg("against_ids"), py::arg("categories") = py::none(),
             py::arg("masks") = py::none(), py::arg("groups") = py::none(),
             py::arg("against_categories") = py::none(), py::arg("against_masks") = py::none(),
             py::arg("against_groups") = py::none(),
             "find_poses with the contact of each pair (obbsat::pair_finder::find_contacts): (pairs, columns).")
        .def_property_readonly("stats", &scene_finder::stats, "What the last query did.")
        .def("find_corners64", &scene_finder::find<obbsat::rect_records64>, py::arg("boxes"), py::arg("against"),
             py::arg("ids"), py::arg("against_ids"), py::arg("categories") = py::none(), py::arg("masks") = py::none(), py::arg("groups") = py::none(),
             py::arg("against_categories") = py::none(), py::arg("against_masks") = py::none(),
             py::arg("against_groups") = py::none(),
             "find_pairs_corners64 through the finder; the pairs are a copy of its buffer.")
        .def("find_poses64", &scene_finder::find<obbsat::pose_records64>, py::arg("boxes"), py::arg("against"),
             py::arg("ids"), py::arg("against_ids"), py::arg("categories") = py::none(), py::arg("masks") = py::none(), py::arg("groups") = py::none(),
             py::arg("against_categories") = py::none(), py::arg("against_masks") = py::none(),
             py::arg("against_groups") = py::none(),
             "find_pairs_poses64 through the finder; the pairs are a copy of its buffer.")
        .def("find_contacts_corners64", &scene_finder::find_contacts<obbsat::rect_records64>, py::arg("boxes"),
             py::arg("against"), py::arg("ids"), py::arg("against_ids"), py::arg("categories") = py::none(),
             py::arg("masks") = py::none(), py::arg("groups") = py::none(),
             py::arg("against_categories") = py::none(), py::arg("against_masks") = py::none(),
             py::arg("against_groups") = py::none(),
             "find_corners64 with the double contact of each pair (obbsat::pair_finder::find_contacts64): "
             "(pairs, float64 columns).")
        .def("find_contacts_poses64", &scene_finder::find_contacts<obbsat::pose_records64>, py::arg("boxes"),
             py::arg("against"), py::arg("ids"), py::arg("against_ids"), py::arg("categories") = py::none(),
             py::arg("masks") = py::none(), py::arg("groups") = py::none(),
             py::arg("against_categories") = py::none(), py::arg("against_masks") = py::none(),
             py::arg("against_groups") = py::none(),
             "find_poses64 with the double contact of each pair (obbsat::pair_finder::find_contacts64): "
             "(pairs, float64 columns).")
        .def("track_events", &scene_finder::track_events, py::arg("on"),
             "Turns the begin/end events on (the next query begins every pair) or off.")
        .def("began", [](scene_finder& f) { return f.events(true); },
             "The pairs that began colliding at the last query: uint32 (K, 2) sorted, a copy; uint64 id pairs "
             "when its rows had ids (ValueError when events are off).")
        .def("ended", [](scene_finder& f) { return f.events(false); },
             "The pairs that ended colliding at the last query: uint32 (K, 2) sorted, a copy; uint64 id pairs "
             "when its rows had ids (ValueError when events are off).");
    m.def("corner_bounds", &bounds_of<obbsat::rect_records>, py::arg("boxes"),
          "The bounds lo_x, lo_y, hi_x, hi_y of corner boxes (float32 (N, 8) or (N, 4, 2), or a RectRecords) "
          "as obbsat/ref/bounds.hpp computes them: float32 (N, 4).");
    m.def("corner_bounds64", &bounds_of<obbsat::rect_records64>, py::arg("boxes"),
          "The float bounds of float64 corner boxes (or a RectRecords64) rounded outward (obbsat/ref/bounds64.hpp): "
          "float32 (N, 4).");
    m.def("pose_bounds64", &bounds_of<obbsat::pose_records64>, py::arg("boxes"),
          "The float bounds of float64 poses (or a PoseRecords64) rounded outward (obbsat/ref/bounds64.hpp): "
          "float32 (N, 4).");
    m.def("pose_bounds", &bounds_of<obbsat::pose_records>, py::arg("boxes"),
          "The bounds lo_x, lo_y, hi_x, hi_y of poses (float32 (N, 6), or a PoseRecords) as "
          "obbsat/ref/bounds.hpp computes them: float32 (N, 4).");
    m.def("make_pose_scene", &make_pose_scene, py::arg("boxes"), py::arg("sizes"), py::arg("pairs_per_box"),
          py::arg("seed"), "The library's seeded scene of poses (obbsat::make_pose_scene): float32 (N, 6).");
    m.def("runnable_backends", &runnable_backends, "Backends this build and CPU run, best first.");
    m.def("compiled_backends", &compiled_backend_names, "Backends compiled into this build, best first.");
    m.def("methods", &method_names, py::arg("store"),
          "The methods that run on a store ('corners' or 'poses'), in the library's order.");
    m.def("resolved_backend", &resolved_backend, py::arg("name"),
          "The backend a request resolves to here (OBBSAT_BACKEND applies to 'auto').");
    m.def("make_scene", &make_scene, py::arg("rects"), py::arg("pairs"), py::arg("density"), py::arg("seed"),
          "The library's seeded benchmark scene: (float32 (N, 8) corners, uint32 (M, 2) pairs).");
    m.attr("__version__") = OBBSAT_VERSION_STRING;
}
