#include "sweep_mpi.hpp"

#include "db/sample_codec.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <mpi.h>
#include <stdexcept>
#include <string>
#include <thread>
#include <utility>

namespace rockfall::app::mpi {
namespace {

// Message tags. Rank r != 0 to rank 0: request (int: indices wanted), results (bytes of
// encode_sample), interrupt (int: the signal), done (nothing, the last message). Rank 0 to
// rank r: chunk (int64 indices; none: no more), stop (nothing).
enum Tag : int { request = 1, results, interrupt_tag, done, chunk, stop_tag };

constexpr int owner = 0;

void check(int code, const char* what) {
    if (code == MPI_SUCCESS) return;
    char text[MPI_MAX_ERROR_STRING];
    int length = 0;
    MPI_Error_string(code, text, &length);
    throw std::runtime_error(std::string("MPI ") + what + " failed: " + std::string(text, length));
}

void send_bytes(const std::string& bytes, int to, int tag) {
    check(MPI_Send(bytes.data(), static_cast<int>(bytes.size()), MPI_BYTE, to, tag, MPI_COMM_WORLD),
          "send");
}

std::string receive_bytes(const MPI_Status& status) {
    int size = 0;
    MPI_Get_count(&status, MPI_BYTE, &size);
    std::string bytes(static_cast<std::size_t>(size), '\0');
    check(MPI_Recv(bytes.data(), size, MPI_BYTE, status.MPI_SOURCE, status.MPI_TAG, MPI_COMM_WORLD,
                   MPI_STATUS_IGNORE),
          "receive");
    return bytes;
}

void send_int(int value, int to, int tag) {
    check(MPI_Send(&value, 1, MPI_INT, to, tag, MPI_COMM_WORLD), "send");
}

int receive_int(const MPI_Status& status) {
    int value = 0;
    check(MPI_Recv(&value, 1, MPI_INT, status.MPI_SOURCE, status.MPI_TAG, MPI_COMM_WORLD,
                   MPI_STATUS_IGNORE),
          "receive");
    return value;
}

// A message waiting from `from` (MPI_ANY_SOURCE for any), if there is one.
std::optional<MPI_Status> waiting_message(int from) {
    int flag = 0;
    MPI_Status status;
    check(MPI_Iprobe(from, MPI_ANY_TAG, MPI_COMM_WORLD, &flag, &status), "probe");
    if (flag == 0) return std::nullopt;
    return status;
}

// Indices a rank with `threads` threads asks for at a time, and below how many waiting ones
// it asks again: two rounds of work queued, so that no thread waits for a message.
int chunk_for(int threads) { return 2 * threads; }

// Rank 0's view of the sweep: its own runner and the other ranks, fed from `pending` in order.
class OwnerSource final : public SampleSource {
  public:
    OwnerSource(int ranks, const risk::SweepSpec& spec, const engine::Scenario& base,
                std::vector<std::int64_t> pending, const risk::RunnerOptions& options,
                std::atomic<int>& interrupt, std::shared_ptr<bool> others_done)
        : pending_(std::move(pending)),
          threads_(options.threads),
          local_(spec, base, options),
          interrupt_(interrupt),
          others_(ranks - 1),
          others_done_(std::move(others_done)) {}

    std::vector<risk::SampleResult> collect(std::chrono::milliseconds timeout) override {
        const auto deadline = std::chrono::steady_clock::now() + timeout;
        std::vector<risk::SampleResult> collected;
        for (;;) {
            poll(collected);
            feed_local();
            for (risk::SampleResult& result :
                 local_.collect(std::chrono::milliseconds(collected.empty() ? 1 : 0)))
                collected.push_back(std::move(result));
            if (!collected.empty() || finished() || std::chrono::steady_clock::now() >= deadline)
                return collected;
            // This rank's threads are done (collect returned at once) and the others are not:
            // wait a little rather than spin on MPI_Iprobe against the ranks sharing the node.
            if (local_.finished()) std::this_thread::sleep_for(std::chrono::milliseconds(1));
        }
    }

    void stop() override {
        if (stopping_) return;
        stopping_ = true;
        local_.stop();
        // Not to a rank that said it is done: it is in MPI_Finalize and would not receive it.
        for (int rank = 1; rank <= others_; ++rank)
            if (!done_by_rank_[static_cast<std::size_t>(rank)])
                check(MPI_Send(nullptr, 0, MPI_BYTE, rank, stop_tag, MPI_COMM_WORLD), "send");
    }

    bool finished() const override { return local_.finished() && done_ == others_; }

  private:
    std::vector<std::int64_t> next_chunk(int wanted) {
        if (stopping_) return {};
        const std::size_t end =
            std::min(pending_.size(), next_ + static_cast<std::size_t>(std::max(wanted, 1)));
        std::vector<std::int64_t> indices(pending_.begin() + static_cast<std::ptrdiff_t>(next_),
                                          pending_.begin() + static_cast<std::ptrdiff_t>(end));
        next_ = end;
        return indices;
    }

    void feed_local() {
        if (local_closed_ || local_.waiting() >= static_cast<std::size_t>(threads_)) return;
        const std::vector<std::int64_t> indices = next_chunk(chunk_for(threads_));
        if (indices.empty()) {
            local_.close();
            local_closed_ = true;
        } else {
            local_.add(indices);
        }
    }

    // Answers every message waiting from the other ranks.
    void poll(std::vector<risk::SampleResult>& collected) {
        while (const std::optional<MPI_Status> status = waiting_message(MPI_ANY_SOURCE)) {
            switch (status->MPI_TAG) {
                case request: {
                    const std::vector<std::int64_t> indices = next_chunk(receive_int(*status));
                    check(MPI_Send(indices.data(), static_cast<int>(indices.size()), MPI_INT64_T,
                                   status->MPI_SOURCE, chunk, MPI_COMM_WORLD),
                          "send");
                    break;
                }
                case results:
                    for (risk::SampleResult& result : db::decode_samples(receive_bytes(*status)))
                        collected.push_back(std::move(result));
                    break;
                case interrupt_tag: {
                    const int signal = receive_int(*status);
                    if (interrupt_.load() == 0) interrupt_.store(signal);
                    break;
                }
                case done:
                    receive_bytes(*status);
                    done_by_rank_[static_cast<std::size_t>(status->MPI_SOURCE)] = true;
                    if (++done_ == others_) *others_done_ = true;
                    break;
                default:
                    throw std::runtime_error("MPI: rank " + std::to_string(status->MPI_SOURCE) +
                                             " sent an unknown message (tag " +
                                             std::to_string(status->MPI_TAG) + ")");
            }
        }
    }

    const std::vector<std::int64_t> pending_;
    std::size_t next_ = 0;
    const int threads_;
    risk::SweepRunner local_;
    bool local_closed_ = false;
    bool stopping_ = false;
    std::atomic<int>& interrupt_;
    const int others_;
    int done_ = 0;
    std::vector<bool> done_by_rank_ = std::vector<bool>(static_cast<std::size_t>(others_) + 1);
    std::shared_ptr<bool> others_done_;
};

}  // namespace

Session::Session() {
    int provided = 0;
    check(MPI_Init_thread(nullptr, nullptr, MPI_THREAD_FUNNELED, &provided), "init");
    MPI_Comm_rank(MPI_COMM_WORLD, &rank_);
    MPI_Comm_size(MPI_COMM_WORLD, &size_);
}

Session::~Session() {
    if (rank_ == owner && !setup_sent_) {
        // The owner ends without a sweep (a refused command line, a complete run): the other
        // ranks wait for the setup and get none.
        std::int64_t size = -1;
        MPI_Bcast(&size, 1, MPI_INT64_T, owner, MPI_COMM_WORLD);
    }
    MPI_Finalize();
}

void Session::send_setup(const Setup& setup) {
    const nlohmann::json json = {{"scenario_text", setup.scenario_text},
                                 {"scenario_path", setup.scenario_path},
                                 {"seed", setup.seed},
                                 {"samples", setup.samples},
                                 {"method", setup.method},
                                 {"trajectory_interval", setup.trajectory_interval}};
    std::string bytes = json.dump();
    auto size = static_cast<std::int64_t>(bytes.size());
    check(MPI_Bcast(&size, 1, MPI_INT64_T, owner, MPI_COMM_WORLD), "broadcast");
    check(MPI_Bcast(bytes.data(), static_cast<int>(size), MPI_BYTE, owner, MPI_COMM_WORLD),
          "broadcast");
    setup_sent_ = true;
}

std::optional<Setup> Session::receive_setup() {
    std::int64_t size = 0;
    check(MPI_Bcast(&size, 1, MPI_INT64_T, owner, MPI_COMM_WORLD), "broadcast");
    if (size < 0) return std::nullopt;
    std::string bytes(static_cast<std::size_t>(size), '\0');
    check(MPI_Bcast(bytes.data(), static_cast<int>(size), MPI_BYTE, owner, MPI_COMM_WORLD),
          "broadcast");
    const nlohmann::json json = nlohmann::json::parse(bytes);
    Setup setup;
    setup.scenario_text = json.at("scenario_text").get<std::string>();
    setup.scenario_path = json.at("scenario_path").get<std::string>();
    setup.seed = json.at("seed").get<std::uint64_t>();
    setup.samples = json.at("samples").get<std::int64_t>();
    setup.method = json.at("method").get<std::string>();
    setup.trajectory_interval = json.at("trajectory_interval").get<double>();
    return setup;
}

std::unique_ptr<SampleSource> Session::owner_source(const risk::SweepSpec& spec,
                                                    const engine::Scenario& base,
                                                    std::vector<std::int64_t> pending,
                                                    const risk::RunnerOptions& options,
                                                    std::atomic<int>& interrupt) {
    return std::make_unique<OwnerSource>(size_, spec, base, std::move(pending), options, interrupt,
                                         others_done_);
}

int Session::serve(const risk::SweepSpec& spec, const engine::Scenario& base,
                   const risk::RunnerOptions& options, const std::atomic<int>& interrupt) {
    risk::SweepRunner runner(spec, base, options);
    bool requested = false;
    bool no_more = false;
    bool interrupt_sent = false;
    std::int64_t sent = 0;
    for (;;) {
        if (!no_more && !requested &&
            runner.waiting() < static_cast<std::size_t>(options.threads)) {
            send_int(chunk_for(options.threads), owner, request);
            requested = true;
        }
        while (const std::optional<MPI_Status> status = waiting_message(owner)) {
            if (status->MPI_TAG == chunk) {
                int count = 0;
                MPI_Get_count(&*status, MPI_INT64_T, &count);
                std::vector<std::int64_t> indices(static_cast<std::size_t>(count));
                check(MPI_Recv(indices.data(), count, MPI_INT64_T, owner, chunk, MPI_COMM_WORLD,
                               MPI_STATUS_IGNORE),
                      "receive");
                requested = false;
                if (indices.empty()) {
                    no_more = true;
                    runner.close();
                } else if (!no_more) {
                    runner.add(indices);
                }
            } else if (status->MPI_TAG == stop_tag) {
                receive_bytes(*status);
                no_more = true;
                runner.stop();
            } else {
                throw std::runtime_error("MPI: rank 0 sent an unknown message (tag " +
                                         std::to_string(status->MPI_TAG) + ")");
            }
        }
        if (interrupt.load() != 0 && !interrupt_sent) {
            send_int(interrupt.load(), owner, interrupt_tag);
            interrupt_sent = true;
        }
        std::string bytes;
        const std::int64_t before = sent;
        for (const risk::SampleResult& result : runner.collect(std::chrono::milliseconds(2))) {
            db::encode_sample(result, bytes);
            ++sent;
        }
        if (!bytes.empty()) send_bytes(bytes, owner, results);
        pause_after_samples(pause_after_, before, sent);
        if (no_more && !requested && runner.finished()) break;
    }
    check(MPI_Send(nullptr, 0, MPI_BYTE, owner, done, MPI_COMM_WORLD), "send");
    return 0;
}

bool Session::others_running() const { return setup_sent_ && !*others_done_; }

void Session::abort(int code) {
    MPI_Abort(MPI_COMM_WORLD, code);
    std::abort();
}

}  // namespace rockfall::app::mpi
