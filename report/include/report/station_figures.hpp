#pragma once
/// `rockfall query DB stations`: what the rocks carried past each station, and seed 000's two
/// figures about motion from a sweep: the rate of velocity change V' = (b - a) / a between the
/// toe and the station 4 m from it against the rolling coefficient Cr = w r / v at 4 m
/// (Figure 5), and the angular speed against the speed at the toe (Figure 6), by shape.

#include "report/query_table.hpp"
#include "report/svg_plot.hpp"

#include "db/station_values.hpp"
#include "risk/statistics.hpp"

#include <cstdint>
#include <limits>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

namespace rockfall::report {

/// The rocks of one results database.
struct StationSet {
    /// Label in legends and tables (short: the file's stem), the file it was read from and
    /// the run's scenario name.
    std::string label;
    std::string database;
    std::string scenario;
    /// Every rock with station rows (db::read_rock_stations).
    std::vector<db::RockStations> rocks;
};

/// Seed 000's stations: V' is read between the toe and 4 m past it.
inline constexpr double toe_station_m = 0.0;
inline constexpr double far_station_m = 4.0;

/// The stations' distances from the toe, m, in station order (the first rock's rows; every
/// rock of a sweep has the same). Throws std::invalid_argument naming the database when it has
/// no station rows (a scenario without stations, or no samples).
std::vector<double> station_distances(const StationSet& set);

/// Index of the station `distance` m past the toe (within 1 mm); throws std::invalid_argument
/// naming the database, what the station is for (`purpose`) and the stations it has.
std::size_t station_at(const StationSet& set, double distance, const std::string& purpose);

/// The set's shapes (samples.shape) in the figures' order: sphere, massive, planar, then the
/// others by name.
std::vector<std::string> shapes_of(const StationSet& set);

/// The values of one group of rocks at one station: the lowest and highest third of Cr.
struct CrThird {
    /// Rocks in the third (n / 3 of the n points, rounded down).
    std::int64_t rocks = 0;
    /// Range of Cr in the third.
    double cr_min = std::numeric_limits<double>::quiet_NaN();
    double cr_max = std::numeric_limits<double>::quiet_NaN();
    /// Mean V' of the third, and how many of its rocks slowed down (V' < 0).
    double mean_velocity_change = std::numeric_limits<double>::quiet_NaN();
    std::int64_t negative = 0;
};

/// The points of one shape: x and y of the figure, one per rock.
struct ShapePoints {
    /// samples.shape (sphere, massive, planar, custom, a named shape, generated).
    std::string shape;
    std::vector<double> x;
    std::vector<double> y;
    /// The least-squares line of y on x; empty below 2 distinct x.
    std::optional<risk::LineFit> fit;
};

/// One figure's data for one database.
struct MotionTrend {
    /// The set's label.
    std::string label;
    /// Distances from the toe of the stations read, m: V' from `toe` to `far` and Cr at `far`
    /// (Figure 5), or w and v at `toe` (Figure 6; far = toe).
    double toe = 0.0;
    double far = 0.0;
    /// Points by shape (sphere, massive, planar first), and over all shapes.
    std::vector<ShapePoints> shapes;
    ShapePoints all;
    /// Figure 5 only: the lowest and highest third of Cr.
    CrThird lower;
    CrThird upper;
};

/// Figure 5's data: x = Cr at 4 m, y = V' from the toe to 4 m, for every rock that crossed
/// both with a finite Cr (and a > 0). Throws std::invalid_argument (station_at) when the
/// stations are missing.
MotionTrend velocity_change_trend(const StationSet& set);

/// Figure 6's data: x = speed (m/s), y = angular speed (rad/s) at the toe, for every rock that
/// crossed it. Throws std::invalid_argument when there is no station at the toe.
MotionTrend spin_speed_trend(const StationSet& set);

/// Figure 5 drawn: V' against Cr with the line V' = 0. One set: colour and marker by shape;
/// several: colour by set, marker by shape.
Plot velocity_change_figure(const std::vector<MotionTrend>& trends, const std::string& title);

/// Figure 6 drawn: angular speed against speed with least-squares lines (per shape for one set,
/// per set over all its shapes for several), slopes in rad/m in the legend.
Plot spin_speed_figure(const std::vector<MotionTrend>& trends, const std::string& title);

/// The station table: per set, shape and station the rocks, those that crossed, and the mean
/// speed, parallel speed, angular speed, Cr and bounce height of those that did.
Table station_table(const std::vector<StationSet>& sets);

/// `stations`: the station table, then each set's Figure 5 and Figure 6 trends where it has the
/// stations (a note otherwise); CSV is the station table only.
void write_stations(std::ostream& out, QueryFormat format, const std::vector<StationSet>& sets);

}  // namespace rockfall::report
