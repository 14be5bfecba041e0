# Included by ctest after the discovered tests (tests/CMakeLists.txt adds it to
# TEST_INCLUDE_FILES): the shipped-lessons run renders nine lessons and is slow under
# sanitizers, so CI's sanitizer pass can exclude it with `ctest -LE no-sanitize`; so is
# building a handout with pandoc and pdflatex.
if(COMMAND set_tests_properties)
  set_tests_properties(ShippedLessons.RunAtDraftQualityAndCache PROPERTIES LABELS no-sanitize)
  # pandoc and pdflatex make the handout: the same under sanitizers, and slow.
  set_tests_properties(LessonHandout.BuildsThePdfBothWaysAndEachCaptionShowsOnce PROPERTIES LABELS no-sanitize)
endif()
