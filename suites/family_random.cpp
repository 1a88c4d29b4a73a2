// Families random and far: a broadphase-like scene from make_scene (tag
// "scene"), plus as many rects again built to kiss scene rects at a zero,
// float-scale or visible gap (tag "kiss:<mode>:<gap>"). The far family emits
// the same scene moved to 1e4, 1e6 and 3e7, rounded once at its new place.
#include "contact_construction.hpp"
#include "draws.hpp"
#include "families.hpp"

#include <algorithm>
#include <string>
#include <vector>

namespace obbsat::suites::detail {

namespace {

struct tagged_scene {
    std::vector<quad> quads;  // exact doubles, rounded only when emitted
    std::vector<pair_index> pairs;
    std::vector<std::string> tags;
};

tagged_scene kissing_scene(seeded_random& random, std::size_t pairs) {
    tagged_scene out;
    const std::size_t scene_pairs = pairs / 2;
    const std::size_t scene_rects = std::max<std::size_t>(8, scene_pairs / 4);
    const scene made = make_scene(
        scene_spec_for(scene_density::typical, scene_rects, scene_pairs, random.next()));
    for (std::size_t i = 0; i < made.rects.size(); ++i) {
        out.quads.push_back(to_quad(made.rects[i]));
    }
    for (const pair_index& p : made.pairs) {
        out.pairs.push_back(p);
        out.tags.emplace_back("scene");
    }
    while (out.pairs.size() < pairs) {
        const auto a = static_cast<std::uint32_t>(random.below(made.rects.size()));
        const contact_mode mode = random_contact_mode(random);
        const gap g = random_gap(random);
        const quad& qa = out.quads[a];
        const double half_width = uniform(random, 0.5, 5.0);
        const double half_height = uniform(random, 0.5, 5.0);
        out.quads.push_back(
            place_against(random, qa, mode, half_width, half_height, g.relative * size_of(qa)));
        out.pairs.push_back(pair_index{a, static_cast<std::uint32_t>(out.quads.size() - 1)});
        out.tags.push_back(std::string("kiss:") + contact_mode_name(mode) + ":" + g.name);
    }
    return out;
}

void emit(suite_builder& out, const tagged_scene& content, vec offset, const std::string& prefix) {
    if (out.full()) {
        return;
    }
    std::vector<std::uint32_t> index(content.quads.size());
    for (std::size_t i = 0; i < content.quads.size(); ++i) {
        index[i] = out.add_rect(to_rect(translated(content.quads[i], offset)));
    }
    for (std::size_t i = 0; i < content.pairs.size(); ++i) {
        out.add_pair(index[content.pairs[i].a], index[content.pairs[i].b], prefix + content.tags[i]);
    }
}

}  // namespace

void build_random(suite_builder& out, seeded_random& random) {
    emit(out, kissing_scene(random, out.remaining()), vec{0.0, 0.0}, "");
}

void build_far(suite_builder& out, seeded_random& random) {
    const tagged_scene content = kissing_scene(random, (out.remaining() + 2) / 3);
    emit(out, content, vec{1e4, 1e4}, "1e4:");
    emit(out, content, vec{-1e6, 1e6}, "1e6:");
    emit(out, content, vec{3e7, -3e7}, "3e7:");
}

}  // namespace obbsat::suites::detail
