#pragma once
// What every engine benchmark prints and measures with: the machine it ran on, how busy it
// was, and wall-clock and thread CPU time.

#include <LinearMath/btScalar.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <string>
#include <thread>
#include <time.h>

namespace rockfall::bench {

// Wall-clock (steady_clock) and CPU time of this thread: the machine is shared, so the CPU
// time shows how much of the wall time went to others.
struct Stopwatch {
    std::chrono::steady_clock::time_point wall_start = std::chrono::steady_clock::now();
    double cpu_start = thread_cpu_seconds();

    static double thread_cpu_seconds() {
        timespec ts{};
        clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
        return static_cast<double>(ts.tv_sec) + 1e-9 * static_cast<double>(ts.tv_nsec);
    }
    double wall() const {
        return std::chrono::duration<double>(std::chrono::steady_clock::now() - wall_start).count();
    }
    double cpu() const { return thread_cpu_seconds() - cpu_start; }
};

inline std::string first_line_with(const std::filesystem::path& file, const std::string& key) {
    std::ifstream in(file);
    for (std::string line; std::getline(in, line);) {
        if (line.rfind(key, 0) == 0) {
            const auto colon = line.find(':');
            return colon == std::string::npos ? line : line.substr(colon + 2);
        }
    }
    return "unknown";
}

inline std::string load_average() {
    std::ifstream in("/proc/loadavg");
    std::string one, five, fifteen;
    in >> one >> five >> fifteen;
    return one + " " + five + " " + fifteen + " (1, 5, 15 min)";
}

inline void print_machine(const char* build_type) {
    std::cout << "machine\n"
              << "  cores (nproc):  " << std::thread::hardware_concurrency() << "\n"
              << "  CPU:            " << first_line_with("/proc/cpuinfo", "model name") << "\n"
              << "  compiler:       " << __VERSION__ << "\n"
              << "  build type:     " << build_type
#ifdef NDEBUG
              << " (asserts off)\n"
#else
              << " (asserts on)\n"
#endif
              << "  Bullet:         " << btGetVersion()
              << (sizeof(btScalar) == 8 ? " double precision\n" : " single precision\n");
}

}  // namespace rockfall::bench
