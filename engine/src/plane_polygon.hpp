#pragma once
// Points of a plane and their convex hull, for contact patches. Private to the engine.

#include <algorithm>

namespace rockfall::engine {

struct Point2 {
    double x;
    double y;
};

// Twice the signed area of the triangle o, a, b (positive counter-clockwise).
inline double cross(const Point2& o, const Point2& a, const Point2& b) {
    return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x);
}

// Writes to `hull` the indices into `points` (n of them, at most 16) of their convex hull,
// counter-clockwise and without collinear points (Andrew's monotone chain); returns how many.
// Fewer than three distinct points come back as they are.
inline int convex_hull(const Point2* points, int n, int* hull) {
    int order[16];
    n = std::min(n, 16);
    for (int i = 0; i < n; ++i) {
        order[i] = i;
    }
    std::sort(order, order + n, [&](int a, int b) {
        return points[a].x < points[b].x ||
               (points[a].x == points[b].x && points[a].y < points[b].y);
    });
    if (n < 3) {
        std::copy(order, order + n, hull);
        return n;
    }
    int chain[32];
    int k = 0;
    for (int i = 0; i < n; ++i) {
        while (k >= 2 &&
               cross(points[chain[k - 2]], points[chain[k - 1]], points[order[i]]) <= 0.0) {
            --k;
        }
        chain[k++] = order[i];
    }
    const int lower = k + 1;
    for (int i = n - 1; i-- > 0;) {
        while (k >= lower &&
               cross(points[chain[k - 2]], points[chain[k - 1]], points[order[i]]) <= 0.0) {
            --k;
        }
        chain[k++] = order[i];
    }
    std::copy(chain, chain + k - 1, hull);
    return k - 1;
}

}  // namespace rockfall::engine
