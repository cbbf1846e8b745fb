#pragma once
/// Finished samples as bytes, for sending them between processes (the MPI ranks of a sweep):
/// every field a results database stores, and the rest of the outcome but the wall hits'
/// force histories, bit for bit (doubles as their 8 bytes, NaN included).

#include "db/results_db.hpp"

#include <string>
#include <string_view>
#include <vector>

namespace rockfall::db {

/// Appends `record` to `bytes` (native byte order and sizes: sender and receiver run the same
/// build on machines of one kind).
void encode_sample(const SampleRecord& record, std::string& bytes);

/// Every record of `bytes`, a concatenation of encode_sample's outputs. Throws
/// std::runtime_error when the bytes end inside a record or hold an impossible count.
std::vector<SampleRecord> decode_samples(std::string_view bytes);

}  // namespace rockfall::db
