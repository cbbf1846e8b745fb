#include "report/rock_series.hpp"

#include "shapes/slope.hpp"

#include <algorithm>
#include <cassert>
#include <limits>

namespace rockfall::report {

void SeriesRecorder::add(int rock, const engine::RockState& state) {
    assert(rock >= 0);
    const auto index = static_cast<std::size_t>(rock);
    if (series_.size() <= index) series_.resize(index + 1);
    std::vector<SeriesPoint>& points = series_[index].points;
    SeriesPoint point{state.time, 0.0, state.velocity.norm(), state.position};
    if (!points.empty()) {
        const SeriesPoint& last = points.back();
        assert(state.time >= last.time);
        // Trapezoidal rule for s = integral of |v| dt.
        point.distance =
            last.distance + 0.5 * (last.speed + point.speed) * (point.time - last.time);
    }
    points.push_back(point);
}

std::vector<FrontPoint> cluster_front(const engine::Scenario& scenario,
                                      const std::vector<RockSeries>& series,
                                      const engine::Outcome& outcome) {
    const shapes::Slope slope(scenario.slope);
    std::vector<double> times;
    for (const RockSeries& rock : series) {
        for (const SeriesPoint& p : rock.points) times.push_back(p.time);
    }
    std::sort(times.begin(), times.end());
    times.erase(std::unique(times.begin(), times.end()), times.end());

    std::vector<FrontPoint> front;
    front.reserve(times.size());
    // Per rock, the index of its latest sample at or before the current time.
    std::vector<std::size_t> next(series.size(), 0);
    for (const double t : times) {
        double best_x = -std::numeric_limits<double>::infinity();
        int best_rock = -1;
        for (std::size_t i = 0; i < series.size(); ++i) {
            const std::vector<SeriesPoint>& points = series[i].points;
            while (next[i] < points.size() && points[next[i]].time <= t) ++next[i];
            if (next[i] == 0) continue;
            const bool gone = i < outcome.rocks.size() &&
                              outcome.rocks[i].stop != engine::StopReason::at_rest &&
                              t > outcome.rocks[i].stop_time;
            if (gone) continue;
            const double x = points[next[i] - 1].position.x();
            if (x > best_x) {
                best_x = x;
                best_rock = static_cast<int>(i);
            }
        }
        if (best_rock < 0) continue;
        FrontPoint point;
        point.time = t;
        point.past_toe = best_x - slope.toe_x();
        point.along_surface = slope.distance_along_surface(best_x);
        point.travel = front.empty() ? 0.0 : point.along_surface - front.front().along_surface;
        point.rock = best_rock;
        front.push_back(point);
    }
    return front;
}

SeriesPoint point_at_distance(const RockSeries& series, double s) {
    const std::vector<SeriesPoint>& p = series.points;
    assert(!p.empty());
    const auto after =
        std::upper_bound(p.begin(), p.end(), s,
                         [](double value, const SeriesPoint& q) { return value < q.distance; });
    if (after == p.begin()) return p.front();
    if (after == p.end()) return p.back();
    const SeriesPoint& a = *(after - 1);
    const SeriesPoint& b = *after;
    const double f = (s - a.distance) / (b.distance - a.distance);
    return {a.time + f * (b.time - a.time), s, a.speed + f * (b.speed - a.speed),
            a.position + f * (b.position - a.position)};
}

std::vector<SeriesPoint> sampled_by_distance(const RockSeries& series, std::size_t count) {
    assert(count >= 2);
    std::vector<SeriesPoint> out;
    out.reserve(count);
    for (std::size_t k = 0; k < count; ++k) {
        const double s =
            series.distance() * static_cast<double>(k) / static_cast<double>(count - 1);
        SeriesPoint point = point_at_distance(series, s);
        point.distance = s;
        out.push_back(point);
    }
    return out;
}

}  // namespace rockfall::report
