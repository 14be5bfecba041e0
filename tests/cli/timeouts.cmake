# Included by ctest after the discovered tests (tests/CMakeLists.txt adds it to
# TEST_INCLUDE_FILES). The 100-link chain derives and simulates in seconds; a return to
# the derivation's old growth with the number of bodies (minutes at 50 links) fails here.
if(COMMAND set_tests_properties)
  set_tests_properties(LongChain.HundredLinksDeriveAndSimulateKeepingTheEnergy PROPERTIES TIMEOUT 120)
  # One simulate run of the 100-link chain, then six runs signalled within about another.
  # The second is the program's own time to stop; under the sanitizers every stage runs
  # several times slower (1.5 s at 0.9 of the derivation), so this bound is kept to the
  # Release pass. The other long-chain signal tests run under the sanitizers too.
  set_tests_properties(LongChain.ASignalAtAnyMomentOfTheDerivationEndsTheRunWithinASecond PROPERTIES TIMEOUT 240
                                                                                                     LABELS no-sanitize)
  # The same for solve (about 10 s a run here), render (20 s) and a lesson (45 s): one
  # run unsignalled, then each signalled within a few tenths of it.
  set_tests_properties(LongChain.ASignalAtAnyMomentOfSolveEndsItWithinASecond PROPERTIES TIMEOUT 300 LABELS no-sanitize)
  set_tests_properties(LongChain.ASignalAtAnyMomentOfRenderEndsItWithinASecond PROPERTIES TIMEOUT 600 LABELS no-sanitize)
  set_tests_properties(LongChain.ASignalAtAnyMomentOfALessonEndsItWithinASecond PROPERTIES TIMEOUT 600 LABELS no-sanitize)
endif()
