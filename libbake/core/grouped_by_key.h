// Records (from one or more lists, taken in list order) grouped by a small integer key with a stable counting
// sort: O(records + keys) time, one 32-bit offset per key of memory, and within each key the records keep the order
// they were made in - so a sum over a key's records is the same sum, in the same order, as one accumulated while they
// were made (bit-identical floating point), even when parallel chunks made them in separate lists. Used where a
// dense per-key accumulator would hold mostly empty slots (the crease walk: a few pieces in a million cells).
#pragma once

#include <cstddef>
#include <cstdint>
#include <limits>
#include <utility>
#include <vector>

#include "formats/error.h"

namespace mbk {

template <typename Record>
struct GroupedByKey {
  std::vector<uint32_t> offset;  // key k's records are records[offset[k], offset[k + 1])
  std::vector<Record> records;   // grouped by key, each group in the input's order

  size_t begin(size_t key) const { return offset[key]; }
  size_t end(size_t key) const { return offset[key + 1]; }
};

// The records of several lists, taken in list order; key_of(record) must be < keys. The lists are consumed: each
// is freed once its records are placed, so the records are in memory about once, not twice. Error(runtime_failure)
// beyond 2^32 - 1 records.
template <typename Record, typename KeyOf>
GroupedByKey<Record> group_by_key(std::vector<std::vector<Record>>&& lists, size_t keys, KeyOf&& key_of) {
  GroupedByKey<Record> g;
  g.offset.assign(keys + 1, 0);
  size_t records = 0;
  for (const std::vector<Record>& list : lists) {
    records += list.size();
    for (const Record& r : list) ++g.offset[key_of(r)];
  }
  if (records > std::numeric_limits<uint32_t>::max())
    throw Error(ExitCode::runtime_failure, "internal: more than 2^32 - 1 records to group by key");
  uint32_t start = 0;  // offset[k] becomes the first slot of key k
  for (size_t k = 0; k < keys; ++k) start += std::exchange(g.offset[k], start);
  g.records.resize(records);
  for (std::vector<Record>& list : lists) {
    for (const Record& r : list) g.records[g.offset[key_of(r)]++] = r;  // offset[k] ends at key k's end...
    std::vector<Record>().swap(list);
  }
  for (size_t k = keys; k > 0; --k) g.offset[k] = g.offset[k - 1];  // ... which is key k + 1's first slot
  g.offset[0] = 0;
  return g;
}

}  // namespace mbk
