// Asks the installed exact oracle for one pair of each contact class and
// prints their letters: separated, touching, overlapping.
#include <obbsat/oracle/contact.hpp>

#include <cstdio>

int main() {
    const obbsat::rect unit = {{0, 1}, {1, 1}, {1, 0}, {0, 0}};
    const obbsat::rect far_away = {{3, 1}, {4, 1}, {4, 0}, {3, 0}};
    const obbsat::rect edge_neighbour = {{1, 1}, {2, 1}, {2, 0}, {1, 0}};
    const obbsat::rect inner = {{0.25f, 0.75f}, {0.75f, 0.75f}, {0.75f, 0.25f}, {0.25f, 0.25f}};
    std::printf("%c%c%c\n", obbsat::oracle::contact_letter(obbsat::oracle::classify(unit, far_away)),
                obbsat::oracle::contact_letter(obbsat::oracle::classify(unit, edge_neighbour)),
                obbsat::oracle::contact_letter(obbsat::oracle::classify(unit, inner)));
}
