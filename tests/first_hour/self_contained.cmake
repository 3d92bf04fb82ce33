# A self-contained repository: no file refers to a path outside it (the papers are cited
# through docs/papers.md, the architecture is docs/architecture.md).
add_test(NAME first_hour.self_contained COMMAND bash ${CMAKE_CURRENT_LIST_DIR}/self_contained.sh ${PROJECT_SOURCE_DIR})
set_tests_properties(first_hour.self_contained PROPERTIES LABELS "cli")
