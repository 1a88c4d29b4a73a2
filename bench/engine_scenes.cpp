#include "engine_scenes.hpp"

#include <obbsat/pose_scene.hpp>
#include <obbsat/rect_pose.hpp>
#include <obbsat/scene.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numeric>
#include <vector>

namespace obbsat_bench {

namespace {

/// A rotation in double: (c, s), kept of unit length by renormalising.
struct turn {
    double c = 1;
    double s = 0;
};

/// The rotation whose half-angle tangent is t: exact rational parametrisation.
turn turn_of(double t) {
    const double d = 1.0 + t * t;
    return {(1.0 - t * t) / d, (2.0 * t) / d};
}

/// a then b, renormalised with std::sqrt (correctly rounded, like + - * /).
turn compose(const turn& a, const turn& b) {
    const double c = a.c * b.c - a.s * b.s;
    const double s = a.c * b.s + a.s * b.c;
    const double n = std::sqrt(c * c + s * s);
    return {c / n, s / n};
}

obbsat::rect_pose pose_of(double x, double y, float hx, float hy, const turn& r) {
    return obbsat::rect_pose{{static_cast<float>(x), static_cast<float>(y)},
                             {hx, hy},
                             {static_cast<float>(r.c), static_cast<float>(r.s)}};
}

// ---------------------------------------------------------------- stacks

class stacks_sequence final : public engine_sequence {
public:
    explicit stacks_sequence(std::size_t boxes) : random_(21) {
        constexpr int base = 20;
        constexpr double h = 0.5;        // half extent of a box
        constexpr double slop = 0.002;   // neighbours overlap by this much
        constexpr double pitch = 2 * h - slop;
        constexpr std::size_t per_pyramid = base * (base + 1) / 2 + 1;  // and its ground
        const std::size_t pyramids = (boxes + per_pyramid - 1) / per_pyramid;
        std::size_t columns = 1;
        while (columns * columns < pyramids) {
            ++columns;
        }
        const double spacing = base * pitch + 6.0;
        rest_.reserve(boxes);
        for (std::size_t p = 0; p < pyramids && rest_.size() < boxes; ++p) {
            const double x0 = static_cast<double>(p % columns) * spacing;
            const double y0 = static_cast<double>(p / columns) * spacing;
            // The ground: its top at y0, reaching a box past either end of the base.
            const double width = base * pitch;
            rest_.push_back(pose_of(x0 + 0.5 * (width - pitch), y0 - 0.5, static_cast<float>(0.5 * width + 1.0),
                                    0.5f, turn{}));
            moves_.push_back(false);
            for (int row = 0; row < base && rest_.size() < boxes; ++row) {
                for (int i = 0; i < base - row && rest_.size() < boxes; ++i) {
                    const double x = x0 + (0.5 * row + i) * pitch;
                    const double y = y0 + h - 0.5 * slop + row * pitch;
                    rest_.push_back(pose_of(x, y, static_cast<float>(h), static_cast<float>(h), turn{}));
                    moves_.push_back(true);
                }
            }
        }
        current_ = obbsat::pose_records(rest_);
        step();
    }

    const obbsat::pose_records& poses() const override { return current_; }

    void step() override {
        constexpr float jitter = 0.0005f;        // 0.5 mm in x and y
        constexpr float half_angle = 0.00025f;   // 0.5 mrad
        for (std::size_t i = 0; i < rest_.size(); ++i) {
            if (!moves_[i]) {
                continue;
            }
            obbsat::rect_pose p = rest_[i];
            p.center.x += random_.uniform(-jitter, jitter);
            p.center.y += random_.uniform(-jitter, jitter);
            const turn r = turn_of(static_cast<double>(random_.uniform(-half_angle, half_angle)));
            p.rotation = {static_cast<float>(r.c), static_cast<float>(r.s)};
            current_.set(i, p);
        }
    }

private:
    obbsat::seeded_random random_;
    std::vector<obbsat::rect_pose> rest_;
    std::vector<bool> moves_;
    obbsat::pose_records current_;
};

// ---------------------------------------------------------------- tumbler

class tumbler_sequence final : public engine_sequence {
public:
    explicit tumbler_sequence(std::size_t boxes) : random_(31) {
        const std::size_t per_drum = walls + boxes_per_drum;
        const std::size_t drums = (boxes + per_drum - 1) / per_drum;
        std::size_t columns = 1;
        while (columns * columns < drums) {
            ++columns;
        }
        // The walls' directions: 32 steps of the turn whose half-angle tangent is tan(pi/32).
        const turn wall_step = turn_of(0.098491403357164253);
        turn u{};
        for (std::size_t j = 0; j < walls; ++j) {
            wall_dir_.push_back(u);
            u = compose(u, wall_step);
        }
        for (std::size_t d = 0; d < drums && bodies_.size() + walls_.size() < boxes; ++d) {
            const double cx = static_cast<double>(d % columns) * 2.5 * radius;
            const double cy = static_cast<double>(d / columns) * 2.5 * radius;
            for (std::size_t j = 0; j < walls && bodies_.size() + walls_.size() < boxes; ++j) {
                walls_.push_back({cx, cy, j, bodies_.size() + walls_.size()});
            }
            for (std::size_t k = 0; k < boxes_per_drum && bodies_.size() + walls_.size() < boxes; ++k) {
                body b;
                b.cx = cx;
                b.cy = cy;
                b.row = bodies_.size() + walls_.size();
                b.hx = random_.uniform(0.2f, 0.35f);
                b.hy = random_.uniform(0.2f, 0.35f);
                b.reach = radius - 0.3 - static_cast<double>(random_.uniform(0.0f, 0.25f)) * radius;
                // Somewhere in the lower half, carried: direction (s, -c) of an angle in [-pi/2, pi/2].
                const turn a = turn_of(static_cast<double>(random_.uniform(-1.0f, 1.0f)));
                b.x = a.s * b.reach;
                b.y = -a.c * b.reach;
                b.rotation = turn_of(static_cast<double>(random_.uniform(-1.0f, 1.0f)));
                new_release(b);
                bodies_.push_back(b);
            }
        }
        current_.reserve(boxes);
        for (std::size_t i = 0; i < bodies_.size() + walls_.size(); ++i) {
            current_.push_back(obbsat::rect_pose{{0, 0}, {1, 1}, {1, 0}});
        }
        write();
    }

    const obbsat::pose_records& poses() const override { return current_; }

    void step() override {
        drum_ = compose(drum_, drum_step_);
        for (body& b : bodies_) {
            if (!b.flying) {
                const double x = drum_step_.c * b.x - drum_step_.s * b.y;
                const double y = drum_step_.s * b.x + drum_step_.c * b.y;
                b.x = x;
                b.y = y;
                b.rotation = compose(b.rotation, drum_step_);
                if (b.x > 0 && b.y > b.release_y) {
                    // Thrown with the wall's speed, pushed a little inward, spinning.
                    b.flying = true;
                    b.flown = 0;
                    const double push = static_cast<double>(random_.uniform(0.004f, 0.012f));
                    b.vx = -drum_step_.s * b.y - push * b.x;
                    b.vy = drum_step_.s * b.x - push * b.y;
                    b.spin = turn_of(static_cast<double>(random_.uniform(-0.1f, 0.1f)));
                }
            } else {
                b.vy -= gravity;
                b.x += b.vx;
                b.y += b.vy;
                b.rotation = compose(b.rotation, b.spin);
                ++b.flown;
                const double r2 = b.x * b.x + b.y * b.y;
                if (b.flown >= 4 && b.x * b.vx + b.y * b.vy > 0 && r2 >= b.reach * b.reach) {
                    const double scale = b.reach / std::sqrt(r2);
                    b.x *= scale;
                    b.y *= scale;
                    b.flying = false;
                    new_release(b);
                }
            }
        }
        write();
    }

private:
    static constexpr std::size_t walls = 32;
    static constexpr std::size_t boxes_per_drum = 2000;
    static constexpr double radius = 26.0;
    static constexpr double gravity = 0.01;

    struct body {
        double cx = 0, cy = 0;  // the drum's center
        std::size_t row = 0;
        float hx = 0, hy = 0;
        double reach = 0;       // its radius while carried
        double x = 0, y = 0;    // relative to the drum's center
        double vx = 0, vy = 0;
        turn rotation, spin;
        double release_y = 0;
        bool flying = false;
        int flown = 0;
    };
    struct wall {
        double cx, cy;
        std::size_t index;  // its direction in wall_dir_
        std::size_t row;
    };

    void new_release(body& b) { b.release_y = static_cast<double>(random_.uniform(-0.3f, 0.8f)) * b.reach; }

    void write() {
        // A wall segment: a thin box tangent to the drum, just outside its radius.
        const auto half_length = static_cast<float>(3.2 * radius / walls + 0.2);
        for (const wall& w : walls_) {
            const turn d = compose(wall_dir_[w.index], drum_);
            const double r = radius + 0.15;
            current_.set(w.row, pose_of(w.cx + d.c * r, w.cy + d.s * r, 0.15f, half_length, d));
        }
        for (const body& b : bodies_) {
            current_.set(b.row, pose_of(b.cx + b.x, b.cy + b.y, b.hx, b.hy, b.rotation));
        }
    }

    obbsat::seeded_random random_;
    turn drum_{};
    const turn drum_step_ = turn_of(0.01);  // 0.02 rad per frame
    std::vector<turn> wall_dir_;
    std::vector<wall> walls_;
    std::vector<body> bodies_;
    obbsat::pose_records current_;
};

// ---------------------------------------------------------------- uniform drifting scenes

class drifting_uniform_sequence : public engine_sequence {
public:
    drifting_uniform_sequence(std::size_t boxes, std::uint64_t seed) : random_(seed) {
        obbsat::pose_scene_spec spec;
        spec.seed = seed;
        spec.boxes = boxes;
        spec.sizes = obbsat::scene_sizes::uniform;
        spec.pairs_per_box = 2.0;
        side_ = static_cast<float>(obbsat::pose_scene_side(spec));
        rows_ = obbsat::make_pose_scene(spec);
        for (std::size_t i = 0; i < rows_.size(); ++i) {
            velocity_.push_back(random_velocity());
        }
        current_ = obbsat::pose_records(rows_);
    }

    const obbsat::pose_records& poses() const override { return current_; }

protected:
    obbsat::point random_velocity() {
        return {random_.uniform(-max_speed, max_speed), random_.uniform(-max_speed, max_speed)};
    }
    /// A new box at a random place, as make_pose_scene's uniform sizes.
    obbsat::rect_pose random_box() {
        obbsat::rect_pose p;
        p.center = {random_.uniform(0.0f, side_), random_.uniform(0.0f, side_)};
        p.half_extents = {random_.uniform(0.5f, 1.5f), random_.uniform(0.5f, 1.5f)};
        const turn r = turn_of(static_cast<double>(random_.uniform(-1.0f, 1.0f)));
        p.rotation = {static_cast<float>(r.c), static_cast<float>(r.s)};
        return p;
    }
    void drift() {
        for (std::size_t i = 0; i < rows_.size(); ++i) {
            rows_[i].center.x += velocity_[i].x;
            rows_[i].center.y += velocity_[i].y;
        }
    }
    /// `count` distinct rows drawn at random, marked in `chosen_`.
    void choose(std::size_t count) {
        chosen_.assign(rows_.size(), 0);
        for (std::size_t picked = 0; picked < count && picked < rows_.size();) {
            const auto i = static_cast<std::size_t>(random_.below(rows_.size()));
            if (chosen_[i] == 0) {
                chosen_[i] = 1;
                ++picked;
            }
        }
    }

    static constexpr float max_speed = 0.01f;
    obbsat::seeded_random random_;
    float side_ = 0;
    std::vector<obbsat::rect_pose> rows_;
    std::vector<obbsat::point> velocity_;
    std::vector<std::uint8_t> chosen_;
    obbsat::pose_records current_;
};

/// The filter values of a box, drawn from its id and how many times its filters changed.
struct box_filters {
    std::uint64_t category;
    std::uint64_t mask;
    std::int32_t group;
};

box_filters filters_of(std::uint64_t id, std::uint64_t changes) {
    obbsat::seeded_random draw(id * 0x9e3779b97f4a7c15ull + changes);
    box_filters f;
    f.category = std::uint64_t{1} << draw.below(4);
    f.mask = draw.below(8) == 0 ? ~(std::uint64_t{1} << draw.below(4)) : ~std::uint64_t{0};
    // Groups of a few boxes with neighbouring ids.
    f.group = draw.below(16) == 0 ? static_cast<std::int32_t>(1 + (id / (2 + draw.below(3))) % 100000) : 0;
    return f;
}

class spawn_despawn_sequence final : public drifting_uniform_sequence {
public:
    /// `swap_remove`: a removed row takes the last row in its place instead of the rows after it moving down.
    spawn_despawn_sequence(std::size_t boxes, bool filtered, bool swap_remove = false)
        : drifting_uniform_sequence(boxes, 41), filtered_(filtered), swap_remove_(swap_remove) {
        for (std::size_t i = 0; i < rows_.size(); ++i) {
            ids_.push_back(next_id_++);
            add_filters(ids_.back());
        }
    }

    void step() override {
        drift();
        const std::size_t churn = std::max<std::size_t>(1, rows_.size() / 100);
        choose(churn);
        if (swap_remove_) {
            remove_by_swap();
        } else {
            remove_in_order();
        }
        for (std::size_t k = 0; k < churn; ++k) {
            rows_.push_back(random_box());
            velocity_.push_back(random_velocity());
            ids_.push_back(next_id_++);
            add_filters(ids_.back());
        }
        if (filtered_) {
            // A few boxes change their filters (their own draws: the rows stay spawn_despawn's).
            const std::size_t changed = std::max<std::size_t>(1, rows_.size() / 1000);
            for (std::size_t k = 0; k < changed; ++k) {
                const auto i = static_cast<std::size_t>(filter_random_.below(rows_.size()));
                const box_filters f = filters_of(ids_[i], ++filter_changes_);
                categories_[i] = f.category;
                masks_[i] = f.mask;
                groups_[i] = f.group;
            }
        }
        // The rows a user would pass: a new store each frame.
        current_ = obbsat::pose_records(rows_);
    }

    const std::vector<std::uint64_t>* ids() const override { return &ids_; }
    obbsat::pair_filters filters() const override {
        if (!filtered_) {
            return {};
        }
        return {categories_.data(), masks_.data(), groups_.data()};
    }

private:
    /// Row `from`'s box, velocity, id and filters into row `to`.
    void move_row(std::size_t from, std::size_t to) {
        rows_[to] = rows_[from];
        velocity_[to] = velocity_[from];
        ids_[to] = ids_[from];
        if (filtered_) {
            categories_[to] = categories_[from];
            masks_[to] = masks_[from];
            groups_[to] = groups_[from];
        }
    }
    void keep_rows(std::size_t count) {
        rows_.resize(count);
        velocity_.resize(count);
        ids_.resize(count);
        if (filtered_) {
            categories_.resize(count);
            masks_.resize(count);
            groups_.resize(count);
        }
    }
    /// The chosen rows removed, the rows after each moving down.
    void remove_in_order() {
        std::size_t kept = 0;
        for (std::size_t i = 0; i < rows_.size(); ++i) {
            if (chosen_[i] == 0) {
                move_row(i, kept++);
            }
        }
        keep_rows(kept);
    }
    /// The chosen rows removed from the back, each hole taking the last row.
    void remove_by_swap() {
        std::size_t count = rows_.size();
        for (std::size_t i = rows_.size(); i-- > 0;) {
            if (chosen_[i] != 0) {
                move_row(count - 1, i);
                --count;
            }
        }
        keep_rows(count);
    }
    void add_filters(std::uint64_t id) {
        if (filtered_) {
            const box_filters f = filters_of(id, 0);
            categories_.push_back(f.category);
            masks_.push_back(f.mask);
            groups_.push_back(f.group);
        }
    }

    bool filtered_;
    bool swap_remove_;
    std::vector<std::uint64_t> ids_;
    std::uint64_t next_id_ = 0;
    std::vector<std::uint64_t> categories_, masks_;
    std::vector<std::int32_t> groups_;
    obbsat::seeded_random filter_random_{43};
    std::uint64_t filter_changes_ = 0;
};

class drift_sequence final : public drifting_uniform_sequence {
public:
    // spawn_despawn's seed: the same scene, drifting alike, with no rows changed.
    drift_sequence(std::size_t boxes, bool with_ids) : drifting_uniform_sequence(boxes, 41) {
        if (with_ids) {
            ids_.resize(rows_.size());
            std::iota(ids_.begin(), ids_.end(), std::uint64_t{0});
        }
    }

    void step() override {
        drift();
        // A new store each frame, as spawn_despawn makes.
        current_ = obbsat::pose_records(rows_);
    }

    const std::vector<std::uint64_t>* ids() const override { return ids_.empty() ? nullptr : &ids_; }

private:
    std::vector<std::uint64_t> ids_;  ///< drift_ids: row i's box has id i, every frame
};

class teleports_sequence final : public drifting_uniform_sequence {
public:
    explicit teleports_sequence(std::size_t boxes) : drifting_uniform_sequence(boxes, 51) {}

    void step() override {
        drift();
        choose(std::max<std::size_t>(1, rows_.size() / 50));
        for (std::size_t i = 0; i < rows_.size(); ++i) {
            if (chosen_[i] != 0) {
                rows_[i].center = {random_.uniform(0.0f, side_), random_.uniform(0.0f, side_)};
            }
            current_.set(i, rows_[i]);
        }
    }
};

}  // namespace

const char* engine_scene_name(engine_scene scene) {
    switch (scene) {
        case engine_scene::stacks:
            return "stacks";
        case engine_scene::tumbler:
            return "tumbler";
        case engine_scene::spawn_despawn:
            return "spawn_despawn";
        case engine_scene::spawn_despawn_filtered:
            return "spawn_despawn_filtered";
        case engine_scene::spawn_swap_remove:
            return "spawn_swap_remove";
        case engine_scene::drift:
            return "drift";
        case engine_scene::drift_ids:
            return "drift_ids";
        case engine_scene::teleports:
            return "teleports";
    }
    return "?";
}

std::unique_ptr<engine_sequence> make_engine_sequence(engine_scene scene, std::size_t boxes) {
    switch (scene) {
        case engine_scene::stacks:
            return std::make_unique<stacks_sequence>(boxes);
        case engine_scene::tumbler:
            return std::make_unique<tumbler_sequence>(boxes);
        case engine_scene::spawn_despawn:
            return std::make_unique<spawn_despawn_sequence>(boxes, false);
        case engine_scene::spawn_despawn_filtered:
            return std::make_unique<spawn_despawn_sequence>(boxes, true);
        case engine_scene::spawn_swap_remove:
            return std::make_unique<spawn_despawn_sequence>(boxes, false, true);
        case engine_scene::drift:
            return std::make_unique<drift_sequence>(boxes, false);
        case engine_scene::drift_ids:
            return std::make_unique<drift_sequence>(boxes, true);
        case engine_scene::teleports:
            return std::make_unique<teleports_sequence>(boxes);
    }
    return nullptr;
}

}  // namespace obbsat_bench
