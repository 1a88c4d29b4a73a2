#include "rational_model.hpp"

#include <algorithm>

namespace obbsat::test {

namespace {

using qp = rational_point;

qp to_rational(point p) { return qp{mpq_class(static_cast<double>(p.x)), mpq_class(static_cast<double>(p.y))}; }

bool equal(const qp& a, const qp& b) { return a.x == b.x && a.y == b.y; }

mpq_class cross(const qp& o, const qp& a, const qp& b) {
    return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x);
}

mpq_class dot(const qp& o, const qp& a, const qp& b) {
    return (a.x - o.x) * (b.x - o.x) + (a.y - o.y) * (b.y - o.y);
}

// The point p lies on the closed segment a-b (a may equal b).
bool on_segment(const qp& p, const qp& a, const qp& b) {
    if (equal(a, b)) {
        return equal(p, a);
    }
    return cross(a, b, p) == 0 && dot(p, a, b) <= 0;
}

// The closed segments a0-a1 and b0-b1 share a point, solved as a linear system.
bool segments_intersect(const qp& a0, const qp& a1, const qp& b0, const qp& b1) {
    if (equal(a0, a1)) {
        return on_segment(a0, b0, b1);
    }
    if (equal(b0, b1)) {
        return on_segment(b0, a0, a1);
    }
    const mpq_class dax = a1.x - a0.x, day = a1.y - a0.y;
    const mpq_class dbx = b1.x - b0.x, dby = b1.y - b0.y;
    const mpq_class denominator = dax * dby - day * dbx;
    const mpq_class ox = b0.x - a0.x, oy = b0.y - a0.y;
    if (denominator != 0) {
        // a0 + t (a1 - a0) = b0 + u (b1 - b0)
        const mpq_class t = (ox * dby - oy * dbx) / denominator;
        const mpq_class u = (ox * day - oy * dax) / denominator;
        return t >= 0 && t <= 1 && u >= 0 && u <= 1;
    }
    if (ox * day - oy * dax != 0) {
        return false;  // parallel, on different lines
    }
    // One line: compare the parameters of b0 and b1 along a.
    const mpq_class length2 = dax * dax + day * day;
    const mpq_class t0 = (ox * dax + oy * day) / length2;
    const mpq_class t1 = ((b1.x - a0.x) * dax + (b1.y - a0.y) * day) / length2;
    return std::max(std::min(t0, t1), mpq_class(0)) <= std::min(std::max(t0, t1), mpq_class(1));
}

// Closed point-in-polygon for a simple outline: on an edge, or inside by the
// parity of crossings of a ray towards +x.
bool inside_or_on(const qp& p, const std::vector<qp>& polygon) {
    const std::size_t n = polygon.size();
    bool inside = false;
    for (std::size_t i = 0; i < n; ++i) {
        const qp& a = polygon[i];
        const qp& b = polygon[(i + 1) % n];
        if (on_segment(p, a, b)) {
            return true;
        }
        if ((a.y > p.y) != (b.y > p.y)) {
            const mpq_class x_cross = a.x + (p.y - a.y) * (b.x - a.x) / (b.y - a.y);
            if (p.x < x_cross) {
                inside = !inside;
            }
        }
    }
    return inside;
}

mpq_class twice_signed_area(const std::vector<qp>& polygon) {
    mpq_class sum = 0;
    for (std::size_t i = 0; i < polygon.size(); ++i) {
        const qp& a = polygon[i];
        const qp& b = polygon[(i + 1) % polygon.size()];
        sum += a.x * b.y - a.y * b.x;
    }
    return sum;
}

// Convex hull of points not all collinear: keep the points that lie in no
// closed triangle of three others, then order them by angle about their mean.
std::vector<qp> hull_by_exclusion(const std::vector<qp>& points) {
    std::vector<qp> distinct;
    for (const qp& p : points) {
        if (std::none_of(distinct.begin(), distinct.end(), [&](const qp& q) { return equal(p, q); })) {
            distinct.push_back(p);
        }
    }
    std::vector<qp> kept;
    for (std::size_t i = 0; i < distinct.size(); ++i) {
        bool covered = false;
        std::vector<qp> others;
        for (std::size_t j = 0; j < distinct.size(); ++j) {
            if (j != i) {
                others.push_back(distinct[j]);
            }
        }
        // A point on a segment between two others is not a corner either.
        for (std::size_t a = 0; a < others.size() && !covered; ++a) {
            for (std::size_t b = a + 1; b < others.size() && !covered; ++b) {
                covered = on_segment(distinct[i], others[a], others[b]);
                for (std::size_t c = b + 1; c < others.size() && !covered; ++c) {
                    const std::vector<qp> triangle = {others[a], others[b], others[c]};
                    covered = twice_signed_area(triangle) != 0 && inside_or_on(distinct[i], triangle);
                }
            }
        }
        if (!covered) {
            kept.push_back(distinct[i]);
        }
    }
    qp mean{0, 0};
    for (const qp& p : kept) {
        mean.x += p.x;
        mean.y += p.y;
    }
    mean.x /= static_cast<long>(kept.size());
    mean.y /= static_cast<long>(kept.size());
    auto upper_half = [&](const qp& p) { return p.y > mean.y || (p.y == mean.y && p.x > mean.x); };
    std::sort(kept.begin(), kept.end(), [&](const qp& p, const qp& q) {
        const bool hp = upper_half(p), hq = upper_half(q);
        if (hp != hq) {
            return hp;
        }
        return cross(mean, p, q) > 0;
    });
    return kept;
}

// Sutherland-Hodgman: the part of `subject` on the left of (or on) the line a -> b.
std::vector<qp> clip_left_of(const std::vector<qp>& subject, const qp& a, const qp& b) {
    std::vector<qp> out;
    const std::size_t n = subject.size();
    for (std::size_t i = 0; i < n; ++i) {
        const qp& p = subject[i];
        const qp& q = subject[(i + 1) % n];
        const mpq_class sp = cross(a, b, p);
        const mpq_class sq = cross(a, b, q);
        if (sp >= 0) {
            out.push_back(p);
        }
        if ((sp > 0 && sq < 0) || (sp < 0 && sq > 0)) {
            const mpq_class t = sp / (sp - sq);
            out.push_back(qp{p.x + t * (q.x - p.x), p.y + t * (q.y - p.y)});
        }
    }
    return out;
}

// Triangles of a simple polygon of 3 or 4 corners, counter-clockwise, by
// cutting off an ear (a convex corner whose triangle holds no other corner).
std::vector<std::vector<qp>> triangles_of(std::vector<qp> polygon) {
    if (twice_signed_area(polygon) < 0) {
        std::reverse(polygon.begin(), polygon.end());
    }
    if (polygon.size() == 3) {
        return {polygon};
    }
    for (std::size_t i = 0; i < 4; ++i) {
        const qp& prev = polygon[(i + 3) % 4];
        const qp& corner = polygon[i];
        const qp& next = polygon[(i + 1) % 4];
        const qp& rest = polygon[(i + 2) % 4];
        const std::vector<qp> ear = {prev, corner, next};
        if (cross(prev, corner, next) > 0 && !inside_or_on(rest, ear)) {
            return {ear, {prev, next, rest}};
        }
    }
    // A straight corner: the outline is a triangle already.
    std::vector<qp> corners;
    for (std::size_t i = 0; i < 4; ++i) {
        if (cross(polygon[(i + 3) % 4], polygon[i], polygon[(i + 1) % 4]) != 0) {
            corners.push_back(polygon[i]);
        }
    }
    return {corners};
}

mpq_class twice_overlap_area(const std::vector<qp>& a, const std::vector<qp>& b) {
    std::vector<qp> subject = a;
    if (twice_signed_area(subject) < 0) {
        std::reverse(subject.begin(), subject.end());
    }
    mpq_class total = 0;
    for (const std::vector<qp>& triangle : triangles_of(b)) {
        std::vector<qp> clipped = subject;
        for (std::size_t k = 0; k < 3 && !clipped.empty(); ++k) {
            clipped = clip_left_of(clipped, triangle[k], triangle[(k + 1) % 3]);
        }
        if (clipped.size() >= 3) {
            total += twice_signed_area(clipped);
        }
    }
    return total;
}

bool outline_is_simple(const std::vector<qp>& c) {
    const std::size_t n = c.size();
    for (std::size_t i = 0; i < n; ++i) {
        // Neighbouring edges may share only their common corner.
        const qp& a = c[i];
        const qp& b = c[(i + 1) % n];
        const qp& d = c[(i + 2) % n];
        if (cross(a, b, d) == 0 && dot(b, a, d) > 0) {
            return false;
        }
    }
    if (n == 4) {
        return !segments_intersect(c[0], c[1], c[2], c[3]) && !segments_intersect(c[1], c[2], c[3], c[0]);
    }
    return true;
}

}  // namespace

rational_region rational_region_of(const rect& r) {
    return rational_region_of(
        rational_corners{to_rational(r.ul), to_rational(r.ur), to_rational(r.lr), to_rational(r.ll)});
}

rational_region rational_region_of(const rational_corners& given) {
    const std::vector<qp> corners(given.begin(), given.end());
    bool collinear = true;
    for (std::size_t i = 0; i < 4; ++i) {
        for (std::size_t j = 0; j < 4; ++j) {
            for (std::size_t k = 0; k < 4; ++k) {
                collinear = collinear && cross(corners[i], corners[j], corners[k]) == 0;
            }
        }
    }
    if (collinear) {
        // The two corners farthest apart span the set.
        std::size_t best_i = 0, best_j = 0;
        mpq_class best = -1;
        for (std::size_t i = 0; i < 4; ++i) {
            for (std::size_t j = i; j < 4; ++j) {
                const mpq_class d2 = dot(corners[i], corners[j], corners[j]);
                if (d2 > best) {
                    best = d2;
                    best_i = i;
                    best_j = j;
                }
            }
        }
        if (best == 0) {
            return rational_region{{corners[0]}};
        }
        return rational_region{{corners[best_i], corners[best_j]}};
    }
    std::vector<qp> outline;
    for (std::size_t i = 0; i < 4; ++i) {
        if (!equal(corners[i], corners[(i + 1) % 4])) {
            outline.push_back(corners[i]);
        }
    }
    if (outline_is_simple(outline)) {
        return rational_region{outline};
    }
    return rational_region{hull_by_exclusion(corners)};
}

char rational_contact(const rect& a, const rect& b) {
    return rational_contact(rational_region_of(a), rational_region_of(b));
}

char rational_contact(const rational_region& ra, const rational_region& rb) {
    const std::vector<qp>& pa = ra.outline;
    const std::vector<qp>& pb = rb.outline;
    bool meet = false;
    for (std::size_t i = 0; i < pa.size() && !meet; ++i) {
        for (std::size_t j = 0; j < pb.size() && !meet; ++j) {
            meet = segments_intersect(pa[i], pa[(i + 1) % pa.size()], pb[j], pb[(j + 1) % pb.size()]);
        }
    }
    if (!meet && pb.size() >= 3) {
        meet = inside_or_on(pa[0], pb);
    }
    if (!meet && pa.size() >= 3) {
        meet = inside_or_on(pb[0], pa);
    }
    if (!meet) {
        return 'S';
    }
    if (pa.size() < 3 || pb.size() < 3) {
        return 'T';
    }
    return twice_overlap_area(pa, pb) > 0 ? 'O' : 'T';
}

}  // namespace obbsat::test
