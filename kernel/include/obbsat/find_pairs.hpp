// Scene queries: every colliding pair of a whole scene, with no pair list to
// bring. A broadphase over bounds that contain each rectangle's exact point
// set (obbsat/ref/bounds.hpp) finds the pairs whose bounds overlap, the batch
// kernels of the chosen method decide them, and the colliding ones come back
// as (i, j) pairs sorted by i, then j.
//
// Which pairs are reported, for every method m:
//   exactly the pairs whose bounds overlap and that m calls colliding.
// For m = exact this is the exact answer among all N(N−1)/2 pairs: two
// rectangles that share a point have overlapping bounds (each contains its
// rectangle), so the broadphase loses none. For conservative it contains every
// colliding pair; a false positive of conservative between rectangles whose
// bounds are apart is not reported (they do not touch). For the float methods
// (sat4, sat4_centered, sat4_double, local) the same holds: a false positive
// between rectangles whose bounds are apart is absent; every other verdict is
// the method's own, the same on every backend, thread count and executor
// (collide_options::executor).
//
// The rectangles come as a box_view: a store (pose_records, rect_records;
// checked when it was built) or rows in the caller's memory (rect_pose or
// rect, e.g. a std::vector of them or a numpy array), read in place and
// checked by every query that reads them, in the pass that computes the
// bounds, every row whatever their count (one row, or rows against an empty
// set, are checked too): a non-finite value, a negative half extent or a zero
// rotation vector is refused with invalid_input naming the row and the field,
// prefixed "a: " or "b: " in a query across two sets; no pair is reported then.
//
// Double rows (rect_pose64, rect64 and their stores pose_records64,
// rect_records64; box_view::precision() float64): the methods are those of
// the double stores (obbsat/collide64.hpp: exact, conservative and local on
// poses; exact and conservative on corners), deciding the candidates on the
// doubles as given. The broadphase stays in float32 over bounds rounded
// outward from double bounds that contain each exact point set
// (obbsat/ref/bounds64.hpp), so the statement above holds unchanged: exact
// on doubles is the exact answer over all N(N−1)/2 pairs. Both sets of a
// cross query hold the same kind and precision (invalid_input otherwise).
//
// Pair filters (obbsat/pair_filters.hpp): a box_view may carry a category,
// a collide-with mask and a group per rectangle (box_view::with_filters),
// each side of a cross query its own; a pair the filters refuse is dropped
// by the broadphase before the method sees it, and so never reported. They
// cost 24 bytes per rectangle while the pairs are found, and nothing when
// no view carries any.
//
// Memory: about 100 bytes per rectangle while the pairs are found (one copy
// of the records in the query's own order, its bounds, order and strips;
// about 200 for double rows: their outward bounds as a 32-byte float row in
// the caller's order and a 64-byte double record in the query's order)
// and 8 bytes per reported pair; sorting the pairs takes 8 more bytes per
// pair. find_pairs_each holds no pairs beyond 4096 per thread, however
// crowded the scene (a strip's candidates are tested in blocks of 2048 and
// the pairs found handed on as they come). A pair_finder keeps all of it for
// the next call.
//
// Memory kept between calls: find_pairs and find_pairs_each keep their
// working memory (all of the above but the returned pairs) for the next
// call, which then skips the page faults of fresh memory (about a tenth of
// a cold query of a million boxes); the find_pairs taking `out` writes the
// pairs into the caller's vector, so that a caller keeping it takes no
// fresh memory at all. Only one query's memory is kept, that of
// the last one to end while none was kept; a query that finds it held by
// another running at the same time works in memory of its own. A query
// whose working memory passes 1 GiB (some ten million boxes) keeps none,
// and frees its per-rectangle memory before it sorts the pairs (unless it
// writes them into `out`), so that its peak is the larger of the two
// phases. find_contacts keeps the same working memory, and with a margin
// its candidates and stand-ins too. release_scratch() frees all of it.
#pragma once

#include <obbsat/collide.hpp>
#include <obbsat/pair_filters.hpp>
#include <obbsat/pose_records.hpp>
#include <obbsat/pose_records64.hpp>
#include <obbsat/rect.hpp>
#include <obbsat/rect64.hpp>
#include <obbsat/rect_pose.hpp>
#include <obbsat/rect_pose64.hpp>
#include <obbsat/rect_records.hpp>
#include <obbsat/rect_records64.hpp>

#include <cstddef>
#include <cstdint>
#include <functional>
#include <memory>
#include <vector>

namespace obbsat {

/// The floating-point type of a box_view's rectangles.
enum class precision { float32, float64 };

/// What one query did, for reports and benchmarks.
struct find_pairs_stats {
    std::size_t boxes = 0;       ///< rectangles in the query (both stores for a cross query)
    std::size_t strips = 0;      ///< horizontal strips of the sweep
    std::size_t visits = 0;      ///< extra strip entries of rectangles taller than their strip
    std::size_t candidates = 0;  ///< pairs handed to the method: those whose bounds overlap and that the pair filters let through (pair_finder, method exact, from kept candidates: every kept one)
    std::size_t pairs = 0;       ///< pairs reported
    std::size_t slow_path_pairs = 0;  ///< candidates decided on the exact slow path (method exact)
    bool reused_order = false;   ///< the previous query's order was repaired, not rebuilt
    bool reused_candidates = false;  ///< pair_finder: answered from the candidates the last full query kept, without a sweep
    std::size_t kept_candidates = 0;  ///< pair_finder: candidates of the widened bounds kept for the next calls (of rows still there, with ids)
    bool kept_paused = false;    ///< pair_finder: a full query that kept nothing, as keeping is paused after kept candidates served no call
    /// pair_finder: answered by a plain query (find_pairs' own path) because
    /// the last kept candidates, with the full query that kept them, cost
    /// more per call than a plain query; the finder tries keeping again
    /// after a rest that doubles each time keeping does not pay.
    bool kept_resting = false;
    double bounds_seconds = 0;   ///< bounds, the strips, and the sort keys
    double order_seconds = 0;    ///< sorting, copying the records into the sorted order, visits; pair_finder with ids: carrying the kept candidates over rows that came, went or moved; 0 for a query on one thread that copies strip by strip as it sweeps (then in sweep_seconds)
    double sweep_seconds = 0;    ///< broadphase sweep and the method's kernels
    double kernel_seconds = 0;   ///< the method's kernels alone, summed over the threads (part of the sweep)
    double output_seconds = 0;   ///< mapping back to the caller's indices and sorting
};

/// The rectangles of one side of a scene query, where they are: it holds a
/// pointer and a count, so what it views must outlive the query. Converts
/// implicitly from a store and from a vector of rows.
class box_view {
public:
    /// A pose store, checked when it was built.
    box_view(const pose_records& poses);
    /// A corner store, checked when it was built.
    box_view(const rect_records& rects);
    /// `count` poses in the caller's memory (24 bytes each), checked by every query.
    box_view(const rect_pose* poses, std::size_t count);
    /// `count` corner rectangles in the caller's memory (32 bytes each), checked by every query.
    box_view(const rect* rects, std::size_t count);
    /// The poses of a vector, in place, checked by every query.
    box_view(const std::vector<rect_pose>& poses);
    /// The rectangles of a vector, in place, checked by every query.
    box_view(const std::vector<rect>& rects);
    /// A double pose store, checked when it was built.
    box_view(const pose_records64& poses);
    /// A double corner store, checked when it was built.
    box_view(const rect_records64& rects);
    /// `count` double poses in the caller's memory (48 bytes each), checked by every query.
    box_view(const rect_pose64* poses, std::size_t count);
    /// `count` double corner rectangles in the caller's memory (64 bytes each), checked by every query.
    box_view(const rect64* rects, std::size_t count);
    /// The double poses of a vector, in place, checked by every query.
    box_view(const std::vector<rect_pose64>& poses);
    /// The double rectangles of a vector, in place, checked by every query.
    box_view(const std::vector<rect64>& rects);

    /// Poses or corners.
    store_kind kind() const { return kind_; }
    /// float32 (rect_pose, rect and their stores) or float64 (rect_pose64, rect64 and theirs).
    obbsat::precision precision() const { return precision_; }
    /// The number of rectangles.
    std::size_t size() const { return count_; }
    /// The first value of the first rectangle (a center x or an UL x); nullptr when empty or float64.
    const float* floats() const { return precision_ == obbsat::precision::float32 ? static_cast<const float*>(data_) : nullptr; }
    /// The first value of the first rectangle; nullptr when empty or float32.
    const double* doubles() const { return precision_ == obbsat::precision::float64 ? static_cast<const double*>(data_) : nullptr; }
    /// Values (floats or doubles) from one rectangle to the next: 8 for records and corners, 6 for pose rows.
    std::size_t stride() const { return stride_; }
    /// True for a store (checked when built), false for rows checked by each query.
    bool checked() const { return checked_; }

    /// The same rectangles with pair filters (obbsat/pair_filters.hpp): each
    /// array given holds size() values and must outlive the queries; they
    /// replace the filters this view carried.
    box_view with_filters(const pair_filters& filters) const {
        box_view view = *this;
        view.filters_ = filters;
        return view;
    }
    /// The pair filters of the rectangles; none given by default.
    const pair_filters& filters() const { return filters_; }
    /// The same rows, each with a stable id (ids[r] names row r): a
    /// pair_finder matches rows to the last call's by id (pair_finder below),
    /// so rows may come, go and change places between calls. `count` must be
    /// size() (invalid_input otherwise; `ids` may be nullptr when it is 0);
    /// the ids are read in place, so they must outlive the query. find_pairs
    /// and find_pairs_each ignore them.
    box_view with_ids(const std::uint64_t* ids, std::size_t count) const;
    /// The same rows with the ids of a vector (read in place).
    box_view with_ids(const std::vector<std::uint64_t>& ids) const;
    /// Whether the rows carry ids (with_ids).
    bool has_ids() const { return has_ids_; }
    /// The ids of the rows, one per row; nullptr when they carry none (or are none).
    const std::uint64_t* ids() const { return ids_; }

private:
    const void* data_ = nullptr;  ///< floats or doubles, as precision_ says
    std::size_t count_ = 0;
    std::size_t stride_ = 0;  ///< values from one rectangle to the next
    store_kind kind_ = store_kind::poses;
    obbsat::precision precision_ = obbsat::precision::float32;
    bool checked_ = false;
    pair_filters filters_;  ///< nullptr arrays: the defaults
    const std::uint64_t* ids_ = nullptr;  ///< with_ids: one per row, the caller's
    bool has_ids_ = false;
};

/// A pair of ids (box_view::with_ids): a pair_finder's begin/end events when
/// its rows carry ids.
struct id_pair {
    std::uint64_t a;
    std::uint64_t b;
};

inline bool operator==(const id_pair& x, const id_pair& y) { return x.a == y.a && x.b == y.b; }
inline bool operator!=(const id_pair& x, const id_pair& y) { return !(x == y); }

/// Every pair (i, j), i < j, of `boxes` that collides under options.test,
/// sorted by i then j. Throws invalid_input for a method that does not run on
/// the boxes' kind or for an invalid box, unsupported_backend for a backend
/// this CPU lacks.
std::vector<pair_index> find_pairs(box_view boxes, const collide_options& options);

/// Every pair (i, j), i in `a` and j in `b`, that collides, sorted by i then
/// j; `a` and `b` hold the same kind (invalid_input otherwise).
std::vector<pair_index> find_pairs(box_view a, box_view b, const collide_options& options);

/// find_pairs(boxes, options) written into `out`, in the memory `out` holds:
/// a caller that keeps `out` from one call to the next (a frame loop) gives
/// the answer no fresh memory either, which an answer of over 32 MB (4M
/// pairs) otherwise takes from the OS, page faults included, on every call.
/// `out` changes only once every row is checked.
void find_pairs(box_view boxes, const collide_options& options, std::vector<pair_index>& out);

/// find_pairs(a, b, options) written into `out`, as above.
void find_pairs(box_view a, box_view b, const collide_options& options, std::vector<pair_index>& out);

/// Frees the memory find_pairs, find_pairs_each and find_contacts keep
/// between calls (see "Memory kept between calls" above): after it returns,
/// the library holds none of it until the next such call. Safe to call from
/// any thread at any time; a query running meanwhile keeps its own memory
/// until it ends (and may then leave it for the next call). A pair_finder's
/// memory is its own: destroy it to free it.
void release_scratch();

/// Receives the colliding pairs in chunks of at most 4096 pairs, never from
/// two threads at once, in no particular order (each pair once, i < j for
/// one store, i in a and j in b for two); the pointer is valid only during
/// the call. It may be called on any thread running the query: the caller's,
/// the pool's, or the executor's (collide_options::executor).
using pair_chunk_sink = std::function<void(const pair_index* pairs, std::size_t count)>;

/// Streams the pairs of find_pairs to `sink` without holding them all.
void find_pairs_each(box_view boxes, const collide_options& options, const pair_chunk_sink& sink);
/// Streams the pairs of the cross query to `sink`.
void find_pairs_each(box_view a, box_view b, const collide_options& options, const pair_chunk_sink& sink);

namespace detail {
class pair_search;
class pair_events;
struct frame_contacts64;
}  // namespace detail

struct scene_contacts;    // obbsat/find_contacts.hpp
struct scene_contacts64;  // obbsat/find_contacts.hpp

/// A persistent query for simulations. Its first call on a scene answers as
/// find_pairs does; later full queries widen every bounds by a margin and
/// keep the pairs whose widened bounds overlap, sorted in the caller's indices. A later call with the same number of rectangles checks
/// that each one's bounds still lie inside its widened bounds (exact float
/// comparisons); if so, the kept pairs hold every pair whose bounds overlap
/// now, and the call tests just those (no sweep, no sort). Otherwise it runs
/// the full query again, repairing the previous order instead of sorting
/// anew when it can. The margin follows the motion: each box widened by a
/// share of its larger extent or of the scene's median extent, the share
/// doubled when the kept pairs served fewer than four calls and halved when
/// they served more than 64; a full query keeps at most four times the
/// candidates of the last one plus one pair per box, else it answers as a
/// plain query. Keeping pauses when the kept pairs served no call before a
/// box left its widened bounds (teleports, fast tumbling, rows that change
/// places): the calls are then plain queries (stats().kept_paused), whose
/// bounds pass compares each box's bounds with the last call's widened by
/// the margin (16 bytes per box; after a failed comparison the next ones
/// wait up to 16 calls), and keeping resumes after two calls in a row whose
/// boxes all stayed inside. From 65536 rectangles on, the finder also times
/// its calls: when the kept pairs stop serving, the full query that kept
/// them and the calls they answered are weighed per call against plain
/// queries (two timed then, unless keeping clearly paid: at most three
/// quarters of a plain query), and if keeping cost more the next 32 calls
/// are plain queries (stats().kept_resting), the next such rest twice as
/// long (up to 1024 calls), so that a scene where keeping does not pay (rows
/// swap-removed every call, say) costs about what find_pairs costs. The
/// answer is always the
/// same as a fresh find_pairs on the same data, for every method. No
/// allocation once the buffers have grown. Memory beyond find_pairs': 21
/// bytes per kept pair (about 4.5 per rectangle in a scene of 2 colliding
/// pairs per rectangle), one bit more per kept pair for each thread past the
/// first, 29 per rectangle (its bounds, its key, and the repair of the
/// order), 8 more per rectangle that changed strips since the last full
/// query, and 16 per rectangle once keeping has paused (the probe's bounds).
///
/// Pair filters (box_view::with_filters): the kept candidates hold only the
/// pairs the filters of the calls they serve let through. Each call with
/// filters compares them with a copy of the last call's (up to 20 bytes per
/// rectangle). Without ids a call whose filters differ in any value is a
/// full query that keeps anew; with ids (below) the filters follow the ids:
/// a row whose filters changed is carried over as a new row (its kept pairs
/// dropped, its candidates looked up anew and filtered), so frames whose
/// rows and filters change are answered from the kept candidates. A call
/// that gives an array the last did not, or leaves out one it gave, is a
/// full query either way. The answer is always that of find_pairs with the
/// same filters.
/// Rows with ids (box_view::with_ids): the kept candidates follow each box by
/// its id, so rows may be appended, removed (erased or swap-removed),
/// inserted and reordered between calls; the pairs are still row indices of
/// this call, sorted by (i, j). A call whose rows differ from the last one's
/// carries the kept candidates over at a cost of the change plus a few
/// linear passes: a gone row's candidates are dropped, a new row's are
/// looked up in the kept strips (its widened bounds against every kept
/// box's and the other new ones'), and the sorted kept pairs are mapped to
/// this call's rows, those of rows that changed places against the others
/// sorted apart and merged in. A change of more than an eighth of the rows,
/// or gone and added rows since the last full query passing a quarter of
/// them, makes the call a full query (which keeps again: the scene is the
/// same by id). Two rows with one id throw invalid_input naming both rows and
/// the id, before anything changes. Without ids rows are matched by position
/// as above; a call with ids after calls without matches by position once.
/// A query across two sets takes ids for both sets or for neither (its ids
/// are per set: the same id in a and in b names two boxes). Memory with ids,
/// per rectangle: 8 bytes for the last ids and 18 to 36 for a set of them,
/// 8 for the last rows' places, 1 for the check of their order, and, once a
/// row came or went since the last full query, 16 for the widened bounds and
/// 1 bit per kept pair (those of gone rows); empty and added slots keep their
/// per-rectangle memory until the next full query.
///
/// Moving a pair_finder moves its buffers: the moved-from one holds nothing,
/// and its find, stats, track_events, began and ended throw invalid_input
/// ("... on a moved-from pair_finder ...") until a pair_finder is assigned
/// to it; the events move with the buffers.
///
/// Begin/end events (off by default, and then find keeps nothing for them):
/// with track_events(true), each find also gives the pairs that began and
/// ended colliding since the last call, each sorted by (i, j) as find's pairs
/// are (i < j within one set; i in a, j in b across two). Rows are matched by
/// position, whatever the counts: a pair of a row that no longer exists ends,
/// a pair of a new row begins. When the last call's rows had ids, the events
/// are id pairs instead (began_ids, ended_ids; began and ended then throw
/// invalid_input): the smaller id first within one set, the id in a first
/// across two, sorted by (id, id); a gone box's pairs end, a new box's begin,
/// a box that changed rows keeps its pairs. A call with ids after one without,
/// or the other way round, reports every pair as begun and none ended. The first call after events were turned on
/// reports every pair as begun and none ended; so does a call of the other
/// kind (within one set, across two) than the last, which also ends every pair
/// of the last. A call that throws changes no events. Cost: one linear merge
/// of the last answer and this one, 16 bytes per pair kept for it, no
/// allocation once warm. With ids, the answer is first read as id pairs: a
/// pass over the rows and one over the pairs, the pairs of rows whose ids do
/// not increase with the row sorted apart (few when ids are counted up as
/// boxes are made and rows are appended, erased or swap-removed; all of them
/// when ids are in random order), 32 bytes per pair kept for it.
class pair_finder {
public:
    explicit pair_finder(const collide_options& options);
    ~pair_finder();
    pair_finder(pair_finder&&) noexcept;
    pair_finder& operator=(pair_finder&&) noexcept;
    pair_finder(const pair_finder&) = delete;
    pair_finder& operator=(const pair_finder&) = delete;

    /// The pairs of find_pairs(boxes, options); valid until the next call.
    const std::vector<pair_index>& find(box_view boxes);
    /// The pairs of find_pairs(a, b, options); valid until the next call.
    const std::vector<pair_index>& find(box_view a, box_view b);

    /// The pairs of find(boxes), this call's frame, with the contact of each
    /// (obbsat/find_contacts.hpp; margin 0): contacts[k] is contact_pairs'
    /// on rows pairs[k].a and pairs[k].b of this call (rows of `a` and `b`
    /// across two sets), so a pair that persists from one frame to the next
    /// in the same roles keeps its contact points' feature keys while the
    /// same corners touch the same edges. Float rows only. Throws as find,
    /// and invalid_input for double rows (find_contacts64 takes them) or a
    /// row contacts do not accept (obbsat/contact.hpp), before the frame
    /// changes anything. Valid until the next call; the buffers are kept for
    /// the next frame.
    const scene_contacts& find_contacts(box_view boxes);
    /// The pairs of find(a, b) with their contacts, as above.
    const scene_contacts& find_contacts(box_view a, box_view b);

    /// find_contacts on double rows: the pairs of find(boxes) with their
    /// double contacts (contact64, bit for bit contact_pairs over the same
    /// double rows and pairs; obbsat/find_contacts.hpp), a persisting pair
    /// keeping its points' feature keys as above. Throws as find, and
    /// invalid_input for float rows or a row double contacts do not accept,
    /// before the frame changes anything. Rows of rect_pose64 are copied into
    /// 64-byte records each frame (memory kept for the next one). Valid
    /// until the next call.
    const scene_contacts64& find_contacts64(box_view boxes);
    /// The pairs of find(a, b) with their double contacts, as above.
    const scene_contacts64& find_contacts64(box_view a, box_view b);

    /// What the last call did.
    const find_pairs_stats& stats() const;

    /// Turns the begin/end events on (from the next call, which reports every pair as begun) or off (their buffers freed); on twice keeps them.
    void track_events(bool on);
    /// Whether the begin/end events are on.
    bool tracks_events() const;
    /// The pairs of the last call that were not in the call before it, sorted; empty before the first call; invalid_input when events are off.
    const std::vector<pair_index>& began() const;
    /// The pairs of the call before the last that are not in the last, sorted; empty before the first call; invalid_input when events are off.
    const std::vector<pair_index>& ended() const;
    /// began() when the last call's rows carried ids: id pairs, sorted by (id, id); invalid_input when events are off or the last call had no ids.
    const std::vector<id_pair>& began_ids() const;
    /// ended() when the last call's rows carried ids: id pairs, sorted by (id, id); invalid_input when events are off or the last call had no ids.
    const std::vector<id_pair>& ended_ids() const;

private:
    const scene_contacts& frame_contacts(const box_view& a, const box_view* b);
    const scene_contacts64& frame_contacts64(const box_view& a, const box_view* b);

    std::unique_ptr<detail::pair_search> search_;
    std::unique_ptr<detail::pair_events> events_;  ///< nullptr while events are off
    std::unique_ptr<scene_contacts> contacts_;     ///< find_contacts' last answer, nullptr before its first call
    std::unique_ptr<detail::frame_contacts64> contacts64_;  ///< find_contacts64's, nullptr before its first call
};

}  // namespace obbsat
