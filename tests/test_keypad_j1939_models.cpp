// keypad/j1939_models.hpp: the J1939 side of the model table: a row per model, as many keys as its
// CANopen row, every frame of the two complete manuals documented, and docs/j1939.md's coverage
// table read back against the rows.
#include <doctest/doctest.h>

#include <powerkey/keypad/j1939_codec.hpp>
#include <powerkey/keypad/j1939_models.hpp>
#include <powerkey/keypad/models.hpp>
#include <powerkey/names.hpp>

#include "j1939_rows.hpp"
#include "support.hpp"

#include <cstddef>
#include <fstream>
#include <string>

using namespace j1939_rows;
using powerkey_tests::frame_of;

TEST_CASE("j1939: the model table") {
    for (std::size_t i = 0; i < model_row_count; ++i) {
        const auto m = static_cast<model>(i);
        CAPTURE(i);
        const auto r = powerkey::j1939::row(m);
        REQUIRE(r.has_value());
        CHECK(r->id == m);
        // A keypad's CANopen row, where there is one, has as many keys.
        if (const auto canopen = powerkey::info(m)) CHECK(canopen->keys == r->keys);
    }
    CHECK(powerkey::j1939::row(static_cast<model>(model_row_count)) == errc::value_out_of_range);
    // A value outside the enum, whatever the frame: each frame the decoder answers in place, a
    // frame of another PGN and an 11-bit frame (decode finds the row without a test of the model).
    for (const auto bad : {static_cast<model>(model_row_count), static_cast<model>(0xFF)})
        for (const char* text :
             {"18EFFF21#041B01010121FFFF", "18EFFF21#041BF9030000FF21", "18EF2100#041B0101010100FF",
              "18EFFF21#0001010100FFFFFF", "18EF2100#041B0220FFFFFFFF", "18EF2100#041B0310FFFFFFFF",
              "18A72100#110100000000FFFF", "18A62100#000000000096FFFF", "0CF00400#FF7D7DE015FFF0FF",
              "18EAFF00#00EE00", "181#0011"}) {
            CAPTURE(text);
            CHECK(decode(frame_of(text), bad) == errc::value_out_of_range);
        }
    CHECK(encode(static_cast<model>(0xFF), contact(1, true)) == errc::value_out_of_range);
    // The two complete manuals document every frame.
    for (const auto m : {model::pkp1600si, model::pkp2600si})
        for (std::size_t f = 0; f < feature_count; ++f)
            CHECK(powerkey::j1939::row(m)->frames.of(static_cast<feature>(f)) ==
                  coverage::documented);
    // Every feature and coverage has a name.
    for (std::size_t f = 0; f < feature_count; ++f)
        CHECK(powerkey::is_named(static_cast<feature>(f)));
    CHECK(powerkey::enum_values<coverage>().size() == 4);
}

TEST_CASE("j1939: docs/j1939.md's coverage table is the model table") {
    std::ifstream doc(POWERKEY_SOURCE_DIR "/docs/j1939.md");
    REQUIRE(doc.good());
    std::string line;
    while (std::getline(doc, line) && line.find("<!-- coverage table") == std::string::npos) {
    }
    REQUIRE(std::getline(doc, line));  // the header: the models in enum order
    for (std::size_t i = 0; i < model_row_count; ++i) {
        const auto m = static_cast<model>(i);
        const std::string name(powerkey::to_string(m));
        CHECK(line.find(" " + name + " ") != std::string::npos);
    }
    REQUIRE(std::getline(doc, line));  // |---|
    std::size_t rows = 0;
    while (std::getline(doc, line) && line.starts_with("| ")) {
        CAPTURE(line);
        const auto end = line.find(" |", 2);
        const auto f = powerkey::from_string<feature>(line.substr(2, end - 2));
        REQUIRE(f.has_value());
        CHECK(static_cast<std::size_t>(*f) == rows);  // in enum order, each once
        std::size_t at = end + 2;
        for (std::size_t i = 0; i < model_row_count; ++i) {
            const auto cell = line.find_first_not_of(' ', at);
            REQUIRE(cell != std::string::npos);
            const coverage c = powerkey::j1939::row(static_cast<model>(i))->frames.of(*f);
            CHECK(line[cell] == "AUID"[static_cast<std::size_t>(c)]);
            at = line.find('|', cell) + 1;
        }
        ++rows;
    }
    CHECK(rows == feature_count);
}

// The J1939 row of every value of the model enum's byte: the rows of the table, nothing past it.
namespace {
constexpr bool j1939_rows_bounded() {
    for (unsigned v = 0; v < 256; ++v)
        if (powerkey::j1939::row(static_cast<powerkey::model>(v)).has_value() !=
            (v < powerkey::j1939::model_row_count))
            return false;
    return true;
}
static_assert(j1939_rows_bounded());
}  // namespace

TEST_CASE("a J1939 row for each model of the table, none past it") { CHECK(j1939_rows_bounded()); }
