// error.hpp: the error codes, numbered from 1 (0 is no error and has no name), each with its one
// name (docs/errors.md).
#include <doctest/doctest.h>

#include <powerkey/error.hpp>
#include <powerkey/names.hpp>

#include "support.hpp"

namespace {
using namespace powerkey;
using namespace powerkey_tests;

constexpr name_row errc_rows[] = {
    {"errors.md", 1, "wrong_id_format"},   {"errors.md", 2, "wrong_id"},
    {"errors.md", 3, "wrong_length"},      {"errors.md", 4, "unknown_command"},
    {"errors.md", 5, "index_mismatch"},    {"errors.md", 6, "value_out_of_range"},
    {"errors.md", 7, "reserved_not_zero"}, {"errors.md", 8, "toggle_error"},
    {"errors.md", 9, "size_mismatch"},     {"errors.md", 10, "buffer_too_small"},
    {"errors.md", 11, "sdo_aborted"},      {"errors.md", 12, "unexpected_frame"},
    {"errors.md", 13, "syntax_error"},     {"errors.md", 14, "unknown_object"},
    {"errors.md", 15, "reserved_not_ff"},  {"errors.md", 16, "undocumented"},
};
static_assert(name_table_is<errc>(errc_rows, 0));
static_assert(!is_named(static_cast<errc>(17)));
}  // namespace

TEST_CASE("every errc is named, listed once, and numbered 1..N") {
    CHECK(name_table_is<errc>(errc_rows, 0));
}
