// libFuzzer target: exemplar-graph files (libbake/synth/exemplar_graph.h), read as `graph` and `synth` read them
// (parse_exemplar_graph_text: strict JSON, ids, root, edges, reachability). Any input must end in a graph or an
// mbk::Error, never a crash, a sanitizer report or a hang. Seeds: tests/fuzz/corpus/graph/.
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "formats/error.h"
#include "libbake/synth/exemplar_graph.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  try {
    (void)mbk::parse_exemplar_graph_text(std::string_view(reinterpret_cast<const char*>(data), size),
                                         "fuzz/graph.json");
  } catch (const mbk::Error&) {
  }
  return 0;
}
