// Fuzz target: the mechanism file reader on arbitrary bytes, seeded with the shipped
// mechanisms. Refusing the input (linkage::Error with exit code 2) is the only allowed
// failure; an accepted mechanism's tree and --set must work too.
#include "core/error.hpp"
#include "fuzz/fuzz_support.hpp"
#include "model/mechanism_toml.hpp"
#include "model/spanning_tree.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::filesystem::path file = linkage::fuzz::write_input("mechanism.toml", data, size);
  try {
    linkage::Mechanism mechanism = linkage::read_mechanism_file(file);
    const linkage::SpanningTree tree = linkage::spanning_tree(mechanism);
    (void)linkage::degrees_of_freedom(mechanism);
    for (const linkage::Coordinate& c : tree.coordinates) linkage::set_value(mechanism, c.key + "_dot", 1, "fuzz");
    linkage::validate_initial(mechanism);
    linkage::fuzz::note_accepted();
  } catch (const linkage::Error& e) {
    if (e.code() != linkage::ExitCode::bad_input) throw;
  }
  return 0;
}
