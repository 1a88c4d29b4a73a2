// Three rectangles in, three candidate pairs, three verdicts out.
#include <obbsat/obbsat.hpp>

#include <cstdio>
#include <vector>

int main() {
    // Corners in the order UL, UR, LR, LL.
    const obbsat::rect_records rects(std::vector<obbsat::rect>{
        {{0, 2}, {4, 2}, {4, 0}, {0, 0}},      // 4 x 2, axis-aligned
        {{3, 3}, {5, 1}, {4, 0}, {2, 2}},      // turned 45 degrees, overlaps rect 0
        {{9, 9}, {10, 9}, {10, 8}, {9, 8}},    // far from rect 0
        {{4, 2}, {6, 2}, {6, 0}, {4, 0}},      // shares an edge with rect 0: touching collides
    });
    const std::vector<obbsat::pair_index> pairs = {{0, 1}, {0, 2}, {0, 3}};

    const std::vector<std::uint8_t> verdicts = obbsat::collide_pairs(rects, pairs);
    for (std::size_t i = 0; i < pairs.size(); ++i) {
        std::printf("%u %u %s\n", pairs[i].a, pairs[i].b, verdicts[i] ? "collide" : "apart");
    }
}
