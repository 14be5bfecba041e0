# Included by ctest after the discovered tests (tests/CMakeLists.txt adds it to
# TEST_INCLUDE_FILES). The 100-link chain derives and simulates in seconds; a return to
# the derivation's old growth with the number of bodies (minutes at 50 links) fails here.
if(COMMAND set_tests_properties)
  set_tests_properties(LongChain.HundredLinksDeriveAndSimulateKeepingTheEnergy PROPERTIES TIMEOUT 120)
  # One derivation of the 100-link chain, then four runs signalled within about another.
  set_tests_properties(LongChain.ASignalAtAnyMomentOfTheDerivationEndsTheRunWithinASecond PROPERTIES TIMEOUT 240)
endif()
