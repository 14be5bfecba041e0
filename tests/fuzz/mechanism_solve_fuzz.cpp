// Fuzz target: a mechanism file all the way through `linkage solve` (reader, symbolic
// system, loop closure, the three cases, compiled numbers, the text report) on mutated
// bytes. Refusing the input (linkage::Error with exit code 2) is the only allowed failure;
// a crash, a hang (the driver's time limit), an exception of another kind, or a "nan" in
// the report fails.
#include <regex>
#include <stdexcept>

#include "core/error.hpp"
#include "fuzz/fuzz_support.hpp"
#include "model/mechanism_toml.hpp"
#include "report/mechanism_solution.hpp"
#include "report/mechanism_text.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    linkage::Mechanism mechanism = linkage::read_mechanism(text, "fuzz.toml");
    mechanism.title.clear();  // the check below is for numbers, not for the file's prose
    mechanism.description.clear();
    for (linkage::Parameter& p : mechanism.parameters) p.unit = p.meaning = "";
    if (mechanism.bodies.size() > 8 || mechanism.joints.size() > 8) return 0;  // keeps each input quick
    const linkage::MechanismSolution solution = linkage::work_out_mechanism(
        mechanism, {linkage::CaseId::maximal, linkage::CaseId::generalized, linkage::CaseId::reduced});
    const std::string report = linkage::mechanism_text(solution, linkage::ReportOptions{});
    // A number's sign belongs to it: "-inf" after a space is a number, "O2-inf" a name.
    static const std::regex non_finite(R"((^|[ (=|])-?(nan|inf)($|[ ),*]))");
    if (std::regex_search(report, non_finite)) throw std::logic_error("the report prints a non-finite number");
    linkage::fuzz::note_accepted();
  } catch (const linkage::Error& e) {
    if (e.code() != linkage::ExitCode::bad_input) throw;
  }
  return 0;
}
