// obbsat._core's contact and distance calls (obbsat/contact.hpp,
// obbsat/find_contacts.hpp): register_contacts adds them to the module.
//
// As the collide calls in module.cpp, they take arrays whose memory already
// has the library's layout (float32 C-contiguous poses (N, 6) or corners
// (N, 8) / (N, 4, 2), uint32 C-contiguous pairs (M, 2); the package's
// __init__.py converts anything else first) or a store (RectRecords,
// PoseRecords), and run the library with the GIL released.
//
// Results come back as a dict of new numpy arrays, one row per pair, filled
// without the GIL from the library's array of structures:
//   contacts:  normals float32 (K, 2), depths float32 (K,), counts uint8 (K,),
//              points float32 (K, 2, 2), separations float32 (K, 2),
//              features uint32 (K, 2), each key
//              index_a | type_a << 8 | index_b << 16 | type_b << 24
//              (type 0 a corner, 1 an edge; see obbsat/contact_manifold.hpp);
//              unused points are all zero.
//   distances: distance float32 (K,), a float32 (K, 2), b float32 (K, 2).
// The *64 calls take float64 rows (copied once into pose_records64 or
// rect_records64; find_contacts64 reads them in place, or a double store),
// compute in double and give the same columns in float64.
//
// Errors as in module.cpp: obbsat::invalid_input becomes IndexError when it
// names a pair and ValueError otherwise; unsupported_backend stays itself
// (registered as obbsat.UnsupportedBackendError). Nothing is returned then.
#include "contacts_module.hpp"

#include <obbsat/backend.hpp>
#include <obbsat/contact.hpp>
#include <obbsat/error.hpp>
#include <obbsat/find_contacts.hpp>
#include <obbsat/find_pairs.hpp>
#include <obbsat/method.hpp>
#include <obbsat/pose_records.hpp>
#include <obbsat/pose_records64.hpp>
#include <obbsat/rect.hpp>
#include <obbsat/rect_pose.hpp>
#include <obbsat/rect_records.hpp>
#include <obbsat/rect_records64.hpp>

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <cstddef>
#include <cstdint>
#include <cstring>
#include <limits>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace py = pybind11;

namespace {

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

unsigned threads_of(long long threads) {
    constexpr long long most_threads = std::numeric_limits<unsigned>::max();
    if (threads < 0 || threads > most_threads) {
        throw py::value_error("threads must be >= 0 and <= " + std::to_string(most_threads) +
                              " (0 means every core), not " + std::to_string(threads));
    }
    return static_cast<unsigned>(threads);
}

obbsat::contact_options contact_options_of(double margin, const std::string& backend, long long threads) {
    obbsat::contact_options options;
    options.use = backend_named(backend);
    options.threads = threads_of(threads);
    // A margin beyond float range becomes infinite here, which the library refuses by name.
    options.margin = static_cast<float>(margin);
    return options;
}

obbsat::distance_options distance_options_of(const std::string& backend, long long threads) {
    obbsat::distance_options options;
    options.use = backend_named(backend);
    options.threads = threads_of(threads);
    return options;
}

template <class Real>
bool holds_c(const py::array& a) {
    return py::isinstance<py::array_t<Real>>(a) && (a.flags() & py::array::c_style) != 0;
}

/// The name of a row type's float type, for errors.
template <class Real>
const char* dtype_name() {
    return sizeof(Real) == 8 ? "float64" : "float32";
}

bool is_corner_array(const py::array& a) {
    return (a.ndim() == 2 && a.shape(1) == 8) || (a.ndim() == 3 && a.shape(1) == 4 && a.shape(2) == 2);
}

/// The corners of `a` (rect, or rect64 for float64), read in place.
template <class Rect = obbsat::rect>
std::pair<const Rect*, std::size_t> corners_in_place(const py::array& a, const char* what) {
    using real = decltype(Rect{}.ul.x);
    if (!is_corner_array(a) || !holds_c<real>(a)) {
        throw py::type_error(std::string(what) + ": expected a C-contiguous " + dtype_name<real>() +
                             " array of shape (N, 8) or (N, 4, 2)");
    }
    return {static_cast<const Rect*>(a.data()), static_cast<std::size_t>(a.shape(0))};
}

/// The poses of `a` (rect_pose, or rect_pose64 for float64), read in place.
template <class Pose = obbsat::rect_pose>
std::pair<const Pose*, std::size_t> poses_in_place(const py::array& a, const char* what) {
    using real = decltype(Pose{}.center.x);
    if (a.ndim() != 2 || a.shape(1) != 6 || !holds_c<real>(a)) {
        throw py::type_error(std::string(what) + ": expected a C-contiguous " + dtype_name<real>() +
                             " array of shape (N, 6)");
    }
    return {static_cast<const Pose*>(a.data()), static_cast<std::size_t>(a.shape(0))};
}

/// The pairs of `a`, read in place.
std::pair<const obbsat::pair_index*, std::size_t> pairs_in_place(const py::array& a) {
    if (a.ndim() != 2 || a.shape(1) != 2 || !py::isinstance<py::array_t<std::uint32_t>>(a) ||
        (a.flags() & py::array::c_style) == 0) {
        throw py::type_error("pairs: expected a C-contiguous uint32 array of shape (M, 2)");
    }
    return {static_cast<const obbsat::pair_index*>(a.data()), static_cast<std::size_t>(a.shape(0))};
}

/// Runs `call` without the GIL, turning the library's invalid_input into
/// IndexError (a pair at fault) or ValueError.
template <class Call>
void without_gil(const Call& call) {
    std::string invalid;
    std::string unsupported;
    {
        py::gil_scoped_release release;
        try {
            call();
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
}

/// The columns of K contacts (obbsat::contact, or contact64 in float64), as
/// numpy arrays allocated with the GIL held and filled (scatter) without it.
template <class Contact>
class contact_columns {
    using real = decltype(Contact{}.nx);

public:
    explicit contact_columns(std::size_t count)
        : count_(count),
          normals_(shape({count, 2})),
          depths_(shape({count})),
          counts_(shape({count})),
          points_(shape({count, 2, 2})),
          separations_(shape({count, 2})),
          features_(shape({count, 2})) {}

    /// Copies `contacts` (count of them) into the columns; needs no GIL.
    void fill(const Contact* contacts) {
        real* normals = normals_.mutable_data();
        real* depths = depths_.mutable_data();
        std::uint8_t* counts = counts_.mutable_data();
        real* points = points_.mutable_data();
        real* separations = separations_.mutable_data();
        std::uint32_t* features = features_.mutable_data();
        for (std::size_t k = 0; k < count_; ++k) {
            const Contact& c = contacts[k];
            normals[2 * k] = c.nx;
            normals[2 * k + 1] = c.ny;
            depths[k] = c.depth;
            counts[k] = static_cast<std::uint8_t>(c.point_count);
            for (std::size_t p = 0; p < 2; ++p) {
                const auto& point = c.points[p];
                points[4 * k + 2 * p] = point.x;
                points[4 * k + 2 * p + 1] = point.y;
                separations[2 * k + p] = point.separation;
                features[2 * k + p] = feature_key(point.feature);
            }
        }
    }

    py::dict dict() const {
        py::dict d;
        d["normals"] = normals_;
        d["depths"] = depths_;
        d["counts"] = counts_;
        d["points"] = points_;
        d["separations"] = separations_;
        d["features"] = features_;
        return d;
    }

private:
    static std::vector<py::ssize_t> shape(std::initializer_list<std::size_t> dims) {
        std::vector<py::ssize_t> s;
        for (const std::size_t d : dims) {
            s.push_back(static_cast<py::ssize_t>(d));
        }
        return s;
    }

    /// The four bytes of a feature as one integer, the same on every byte order.
    static std::uint32_t feature_key(const obbsat::contact_feature& f) {
        return std::uint32_t{f.index_a} | std::uint32_t{static_cast<std::uint8_t>(f.type_a)} << 8 |
               std::uint32_t{f.index_b} << 16 | std::uint32_t{static_cast<std::uint8_t>(f.type_b)} << 24;
    }

    std::size_t count_;
    py::array_t<real> normals_;
    py::array_t<real> depths_;
    py::array_t<std::uint8_t> counts_;
    py::array_t<real> points_;
    py::array_t<real> separations_;
    py::array_t<std::uint32_t> features_;
};

/// The columns of K distances (closest_points, or closest_points64 in float64).
template <class Closest>
class distance_columns {
    using real = decltype(Closest{}.distance);

public:
    explicit distance_columns(std::size_t count)
        : count_(count),
          distance_(static_cast<py::ssize_t>(count)),
          a_({static_cast<py::ssize_t>(count), py::ssize_t{2}}),
          b_({static_cast<py::ssize_t>(count), py::ssize_t{2}}) {}

    void fill(const Closest* found) {
        real* distance = distance_.mutable_data();
        real* a = a_.mutable_data();
        real* b = b_.mutable_data();
        for (std::size_t k = 0; k < count_; ++k) {
            distance[k] = found[k].distance;
            a[2 * k] = found[k].ax;
            a[2 * k + 1] = found[k].ay;
            b[2 * k] = found[k].bx;
            b[2 * k + 1] = found[k].by;
        }
    }

    py::dict dict() const {
        py::dict d;
        d["distance"] = distance_;
        d["a"] = a_;
        d["b"] = b_;
        return d;
    }

private:
    std::size_t count_;
    py::array_t<real> distance_;
    py::array_t<real> a_;
    py::array_t<real> b_;
};

/// Runs `compute(out)` (filling `count` results) without the GIL and returns the columns.
template <template <class> class Columns, class Result, class Compute>
py::dict columns_of(std::size_t count, const Compute& compute) {
    Columns<Result> columns(count);
    without_gil([&] {
        std::vector<Result> results(count);
        compute(results.data());
        columns.fill(results.data());
    });
    return columns.dict();
}

/// The stores' pose and corner batches, copied and checked; the error names the batch.
template <class Store, class Row>
Store store_copy(const Row* rows, std::size_t count, const char* what) {
    try {
        return Store(rows, count);
    } catch (const obbsat::invalid_input& e) {
        throw obbsat::invalid_input(std::string(what) + ": " + e.what());
    }
}

/// Contacts of a pair list over an array or a store of either kind.
py::dict contacts_of_pairs(const py::object& boxes, const py::array& pairs, double margin,
                           const std::string& backend, long long threads) {
    const obbsat::contact_options options = contact_options_of(margin, backend, threads);
    const auto [list, count] = pairs_in_place(pairs);
    if (py::isinstance<obbsat::pose_records>(boxes)) {
        const auto& store = boxes.cast<const obbsat::pose_records&>();
        return columns_of<contact_columns, obbsat::contact>(count, [&, list = list, count = count](auto* out) {
            obbsat::contact_pairs(store, list, count, out, options);
        });
    }
    if (py::isinstance<obbsat::rect_records>(boxes)) {
        const auto& store = boxes.cast<const obbsat::rect_records&>();
        return columns_of<contact_columns, obbsat::contact>(count, [&, list = list, count = count](auto* out) {
            obbsat::contact_pairs(store, list, count, out, options);
        });
    }
    const py::array array = boxes.cast<py::array>();
    if (is_corner_array(array)) {
        const auto [rects, rect_count] = corners_in_place(array, "boxes");
        return columns_of<contact_columns, obbsat::contact>(
            count, [&, list = list, count = count, rects = rects, rect_count = rect_count](auto* out) {
                obbsat::contact_pairs(rects, rect_count, list, count, out, options);
            });
    }
    const auto [poses, pose_count] = poses_in_place(array, "boxes");
    return columns_of<contact_columns, obbsat::contact>(
        count, [&, list = list, count = count, poses = poses, pose_count = pose_count](auto* out) {
            obbsat::contact_pairs(poses, pose_count, list, count, out, options);
        });
}

/// Contacts of a[k] against b[k], both arrays of one kind.
py::dict contacts_of_stream(const py::array& a, const py::array& b, double margin, const std::string& backend,
                            long long threads) {
    const obbsat::contact_options options = contact_options_of(margin, backend, threads);
    if (is_corner_array(a)) {
        const auto [rects_a, count_a] = corners_in_place(a, "a");
        const auto [rects_b, count_b] = corners_in_place(b, "b");
        return columns_of<contact_columns, obbsat::contact>(count_a, [&, rects_a = rects_a, count_a = count_a,
                                                                      rects_b = rects_b,
                                                                      count_b = count_b](auto* out) {
            const auto store_a = store_copy<obbsat::rect_records>(rects_a, count_a, "a");
            const auto store_b = store_copy<obbsat::rect_records>(rects_b, count_b, "b");
            obbsat::contact_stream(store_a, store_b, out, options);
        });
    }
    const auto [poses_a, count_a] = poses_in_place(a, "a");
    const auto [poses_b, count_b] = poses_in_place(b, "b");
    return columns_of<contact_columns, obbsat::contact>(count_a, [&, poses_a = poses_a, count_a = count_a,
                                                                  poses_b = poses_b, count_b = count_b](auto* out) {
        const auto store_a = store_copy<obbsat::pose_records>(poses_a, count_a, "a");
        const auto store_b = store_copy<obbsat::pose_records>(poses_b, count_b, "b");
        obbsat::contact_stream(store_a, store_b, out, options);
    });
}

/// Distances of a pair list over an array (copied into a store: the
/// distance calls read stores) or a store of either kind.
py::dict distances_of_pairs(const py::object& boxes, const py::array& pairs, const std::string& backend,
                            long long threads) {
    const obbsat::distance_options options = distance_options_of(backend, threads);
    const auto [list, count] = pairs_in_place(pairs);
    const auto run = [&, list = list, count = count](const auto& store) {
        return columns_of<distance_columns, obbsat::closest_points>(
            count, [&](auto* out) { obbsat::distance_pairs(store, list, count, out, options); });
    };
    if (py::isinstance<obbsat::pose_records>(boxes)) {
        return run(boxes.cast<const obbsat::pose_records&>());
    }
    if (py::isinstance<obbsat::rect_records>(boxes)) {
        return run(boxes.cast<const obbsat::rect_records&>());
    }
    const py::array array = boxes.cast<py::array>();
    if (is_corner_array(array)) {
        const auto [rects, rect_count] = corners_in_place(array, "boxes");
        std::optional<obbsat::rect_records> store;
        without_gil([&, rects = rects, rect_count = rect_count] { store.emplace(rects, rect_count); });
        return run(*store);
    }
    const auto [poses, pose_count] = poses_in_place(array, "boxes");
    std::optional<obbsat::pose_records> store;
    without_gil([&, poses = poses, pose_count = pose_count] { store.emplace(poses, pose_count); });
    return run(*store);
}

/// Distances of a[k] and b[k], both arrays of one kind.
py::dict distances_of_stream(const py::array& a, const py::array& b, const std::string& backend,
                             long long threads) {
    const obbsat::distance_options options = distance_options_of(backend, threads);
    if (is_corner_array(a)) {
        const auto [rects_a, count_a] = corners_in_place(a, "a");
        const auto [rects_b, count_b] = corners_in_place(b, "b");
        return columns_of<distance_columns, obbsat::closest_points>(
            count_a,
            [&, rects_a = rects_a, count_a = count_a, rects_b = rects_b, count_b = count_b](auto* out) {
                const auto store_a = store_copy<obbsat::rect_records>(rects_a, count_a, "a");
                const auto store_b = store_copy<obbsat::rect_records>(rects_b, count_b, "b");
                obbsat::distance_stream(store_a, store_b, out, options);
            });
    }
    const auto [poses_a, count_a] = poses_in_place(a, "a");
    const auto [poses_b, count_b] = poses_in_place(b, "b");
    return columns_of<distance_columns, obbsat::closest_points>(
        count_a, [&, poses_a = poses_a, count_a = count_a, poses_b = poses_b, count_b = count_b](auto* out) {
            const auto store_a = store_copy<obbsat::pose_records>(poses_a, count_a, "a");
            const auto store_b = store_copy<obbsat::pose_records>(poses_b, count_b, "b");
            obbsat::distance_stream(store_a, store_b, out, options);
        });
}

obbsat::contact_options64 contact_options64_of(double margin, const std::string& backend, long long threads) {
    obbsat::contact_options64 options;
    options.use = backend_named(backend);
    options.threads = threads_of(threads);
    options.margin = margin;  // in double, as the boxes: never rounded to float32
    return options;
}

/// The double store of float64 rows, copied and checked without the GIL; an
/// error names the row and field as the float calls do, prefixed by `what`
/// for a stream batch (nothing for the boxes of a pair list).
template <class Store, class Row>
std::optional<Store> double_store_of(const std::pair<const Row*, std::size_t>& rows, const char* what) {
    std::optional<Store> store;
    without_gil([&] {
        if (what == nullptr) {
            store.emplace(rows.first, rows.second);
        } else {
            store.emplace(store_copy<Store>(rows.first, rows.second, what));
        }
    });
    return store;
}

/// Runs `run(store)` on the double store of float64 boxes (N, 8), (N, 4, 2) or (N, 6).
template <class Run>
py::dict on_double_store(const py::array& boxes, const char* what, const Run& run) {
    if (is_corner_array(boxes)) {
        return run(*double_store_of<obbsat::rect_records64>(corners_in_place<obbsat::rect64>(boxes, what), nullptr));
    }
    return run(*double_store_of<obbsat::pose_records64>(poses_in_place<obbsat::rect_pose64>(boxes, what), nullptr));
}

/// Runs `run(store_a, store_b)` on the double stores of two float64 batches of one form.
template <class Run>
py::dict on_double_stores(const py::array& a, const py::array& b, const Run& run) {
    if (is_corner_array(a)) {
        return run(*double_store_of<obbsat::rect_records64>(corners_in_place<obbsat::rect64>(a, "a"), "a"),
                   *double_store_of<obbsat::rect_records64>(corners_in_place<obbsat::rect64>(b, "b"), "b"));
    }
    return run(*double_store_of<obbsat::pose_records64>(poses_in_place<obbsat::rect_pose64>(a, "a"), "a"),
               *double_store_of<obbsat::pose_records64>(poses_in_place<obbsat::rect_pose64>(b, "b"), "b"));
}

/// Contacts of a pair list over float64 boxes, in double (obbsat/contact.hpp's *64 calls).
py::dict contacts_of_pairs64(const py::array& boxes, const py::array& pairs, double margin,
                             const std::string& backend, long long threads) {
    const obbsat::contact_options64 options = contact_options64_of(margin, backend, threads);
    const auto [list, count] = pairs_in_place(pairs);
    return on_double_store(boxes, "boxes", [&, list = list, count = count](const auto& store) {
        return columns_of<contact_columns, obbsat::contact64>(
            count, [&](auto* out) { obbsat::contact_pairs(store, list, count, out, options); });
    });
}

/// Contacts of a[k] and b[k] over float64 batches of one form, in double.
py::dict contacts_of_stream64(const py::array& a, const py::array& b, double margin, const std::string& backend,
                              long long threads) {
    const obbsat::contact_options64 options = contact_options64_of(margin, backend, threads);
    return on_double_stores(a, b, [&](const auto& store_a, const auto& store_b) {
        return columns_of<contact_columns, obbsat::contact64>(
            store_a.size(), [&](auto* out) { obbsat::contact_stream(store_a, store_b, out, options); });
    });
}

/// Distances of a pair list over float64 boxes, in double.
py::dict distances_of_pairs64(const py::array& boxes, const py::array& pairs, const std::string& backend,
                              long long threads) {
    const obbsat::distance_options options = distance_options_of(backend, threads);
    const auto [list, count] = pairs_in_place(pairs);
    return on_double_store(boxes, "boxes", [&, list = list, count = count](const auto& store) {
        return columns_of<distance_columns, obbsat::closest_points64>(
            count, [&](auto* out) { obbsat::distance_pairs(store, list, count, out, options); });
    });
}

/// Distances of a[k] and b[k] over float64 batches of one form, in double.
py::dict distances_of_stream64(const py::array& a, const py::array& b, const std::string& backend,
                               long long threads) {
    const obbsat::distance_options options = distance_options_of(backend, threads);
    return on_double_stores(a, b, [&](const auto& store_a, const auto& store_b) {
        return columns_of<distance_columns, obbsat::closest_points64>(
            store_a.size(), [&](auto* out) { obbsat::distance_stream(store_a, store_b, out, options); });
    });
}

/// The rows of an array, or a store, as the scene query's view: float32
/// arrays and the float stores, or (`doubles`) float64 arrays and the double
/// stores, read in place.
obbsat::box_view view_of(const py::object& boxes, bool doubles) {
    if (!doubles && py::isinstance<obbsat::pose_records>(boxes)) {
        return obbsat::box_view(boxes.cast<const obbsat::pose_records&>());
    }
    if (!doubles && py::isinstance<obbsat::rect_records>(boxes)) {
        return obbsat::box_view(boxes.cast<const obbsat::rect_records&>());
    }
    if (doubles && py::isinstance<obbsat::pose_records64>(boxes)) {
        return obbsat::box_view(boxes.cast<const obbsat::pose_records64&>());
    }
    if (doubles && py::isinstance<obbsat::rect_records64>(boxes)) {
        return obbsat::box_view(boxes.cast<const obbsat::rect_records64&>());
    }
    const py::array array = boxes.cast<py::array>();
    if (is_corner_array(array)) {
        if (doubles) {
            const auto [rects, count] = corners_in_place<obbsat::rect64>(array, "boxes");
            return obbsat::box_view(rects, count);
        }
        const auto [rects, count] = corners_in_place(array, "boxes");
        return obbsat::box_view(rects, count);
    }
    if (doubles) {
        const auto [poses, count] = poses_in_place<obbsat::rect_pose64>(array, "boxes");
        return obbsat::box_view(poses, count);
    }
    const auto [poses, count] = poses_in_place(array, "boxes");
    return obbsat::box_view(poses, count);
}

/// Every colliding pair of a scene (or within the margin) and its contact:
/// (pairs uint32 (K, 2), contact columns); `Answer` scene_contacts for
/// float32 rows, scene_contacts64 (float64 columns, computed in double) for
/// float64 rows.
template <class Answer>
py::tuple scene_contacts_of(const py::object& boxes, const std::string& method, double margin,
                            const std::string& backend, long long threads) {
    constexpr bool doubles = std::is_same<Answer, obbsat::scene_contacts64>::value;
    const auto test = obbsat::parse_method(method);
    if (!test) {
        throw py::value_error("unknown method '" + method + "'");
    }
    obbsat::collide_options options;
    options.test = *test;
    options.use = backend_named(backend);
    options.threads = threads_of(threads);
    const obbsat::box_view view = view_of(boxes, doubles);  // the array or store in `boxes` outlives the call
    Answer found;
    without_gil([&] {
        if constexpr (doubles) {
            obbsat::find_contacts(view, options, margin, found);
        } else {
            obbsat::find_contacts(view, options, static_cast<float>(margin), found);
        }
    });
    const std::size_t count = found.pairs.size();
    py::array_t<std::uint32_t> pairs({static_cast<py::ssize_t>(count), py::ssize_t{2}});
    if (count > 0) {
        py::gil_scoped_release release;
        std::memcpy(pairs.mutable_data(), found.pairs.data(), count * sizeof(obbsat::pair_index));
    }
    return py::make_tuple(pairs, contact_dict(found.contacts.data(), count));
}

/// The columns of `count` contacts (contact or contact64), filled without the GIL.
template <class Contact>
py::dict contact_dict_of(const Contact* contacts, std::size_t count) {
    contact_columns<Contact> columns(count);
    {
        py::gil_scoped_release release;
        columns.fill(contacts);
    }
    return columns.dict();
}

}  // namespace

py::dict contact_dict(const obbsat::contact* contacts, std::size_t count) { return contact_dict_of(contacts, count); }

py::dict contact_dict(const obbsat::contact64* contacts, std::size_t count) {
    return contact_dict_of(contacts, count);
}

void register_contacts(py::module_& m) {
    m.def("contacts_of_pairs", &contacts_of_pairs, py::arg("boxes"), py::arg("pairs"), py::arg("margin"),
          py::arg("backend"), py::arg("threads"),
          "Contacts of a pair list over poses or corners (float32 C-contiguous, or a store); a dict of columns.");
    m.def("contacts_of_stream", &contacts_of_stream, py::arg("a"), py::arg("b"), py::arg("margin"),
          py::arg("backend"), py::arg("threads"), "Contacts of a[k] against b[k]; a dict of columns.");
    m.def("distances_of_pairs", &distances_of_pairs, py::arg("boxes"), py::arg("pairs"), py::arg("backend"),
          py::arg("threads"), "Distances and closest points of a pair list; a dict of columns.");
    m.def("distances_of_stream", &distances_of_stream, py::arg("a"), py::arg("b"), py::arg("backend"),
          py::arg("threads"), "Distances and closest points of a[k] and b[k]; a dict of columns.");
    m.def("contacts_of_pairs64", &contacts_of_pairs64, py::arg("boxes"), py::arg("pairs"), py::arg("margin"),
          py::arg("backend"), py::arg("threads"),
          "Contacts of a pair list over float64 poses or corners, computed in double; a dict of float64 columns.");
    m.def("contacts_of_stream64", &contacts_of_stream64, py::arg("a"), py::arg("b"), py::arg("margin"),
          py::arg("backend"), py::arg("threads"), "Contacts of a[k] and b[k] over float64 rows, in double.");
    m.def("distances_of_pairs64", &distances_of_pairs64, py::arg("boxes"), py::arg("pairs"), py::arg("backend"),
          py::arg("threads"), "Distances of a pair list over float64 poses or corners, in double.");
    m.def("distances_of_stream64", &distances_of_stream64, py::arg("a"), py::arg("b"), py::arg("backend"),
          py::arg("threads"), "Distances of a[k] and b[k] over float64 rows, in double.");
    m.def("find_contacts", &scene_contacts_of<obbsat::scene_contacts>, py::arg("boxes"), py::arg("method"),
          py::arg("margin"), py::arg("backend"), py::arg("threads"),
          "Every colliding pair of a scene (or within the margin) with its contact: (pairs, columns).");
    m.def("find_contacts64", &scene_contacts_of<obbsat::scene_contacts64>, py::arg("boxes"), py::arg("method"),
          py::arg("margin"), py::arg("backend"), py::arg("threads"),
          "find_contacts over float64 rows or a double store, computed in double: (pairs, float64 columns).");
}
