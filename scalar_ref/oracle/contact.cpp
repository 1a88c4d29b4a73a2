#include <obbsat/oracle/contact.hpp>

#include "region_steps.hpp"

namespace obbsat::oracle {

char contact_letter(contact c) {
    switch (c) {
        case contact::separated: return 'S';
        case contact::touching: return 'T';
        case contact::overlapping: return 'O';
    }
    return '?';
}

contact classify(const convex_piece& a, const convex_piece& b) { return steps::classify_pieces(a, b); }

contact classify(const quad_region& a, const quad_region& b) { return steps::classify_regions(a, b); }

contact classify(const rect& a, const rect& b) {
    return classify(region_of(a), region_of(b));
}

bool intersects(const rect& a, const rect& b) {
    return classify(a, b) != contact::separated;
}

}  // namespace obbsat::oracle
