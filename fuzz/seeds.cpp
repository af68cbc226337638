// Writes the seed corpus of every fuzz target into the directory given, one file per seed:
//   <dir>/<target>/<n>
// The seeds are the manual examples (the frames printed in the PK1000 and PKP manuals), in the
// binary frame form of fuzz.hpp or as candump text, so that every run starts from real traffic;
// the encoder's seeds are the same frames decoded, written in the form fill_any reads (put_any).
// The rows are tests/codec_rows.hpp's types: every table (core, PK1000, PKP, the SI manuals'
// rows and the SI reference rows) seeds the decoder for each model of its row, and the
// encode_error_rows seed the encoder with refused messages.
#include "codec_rows.hpp"
#include "fuzz.hpp"
#include "j1939_rows.hpp"
#include "pk1000_rows.hpp"
#include "pkp_rows.hpp"
#include "si_reference_rows.hpp"
#include "si_rows.hpp"

#include <filesystem>
#include <fstream>
#include <map>
#include <span>
#include <string>
#include <string_view>
#include <type_traits>
#include <variant>
#include <vector>

namespace {
using namespace powerkey;
using namespace powerkey_fuzz;

// Core frames printed in the manuals (PK1000 / PKP sections 4-10, 12-13 and 29; the SDO examples
// of object 1008h and 1017h), plus the J1939 switch of PK1000 section 49.
constexpr std::string_view core_frames[] = {
    "000#0115",
    "000#0215",
    "000#8015",
    "000#8115",
    "000#8215",
    "000#0015",
    "000#0100",
    "080#",
    "715#00",
    "715#05",
    "715#04",
    "715#7F",
    "615#4008100000000000",
    "595#410810000B000000",
    "595#00426C696E6B4D61",
    "595#1772696E65000000",
    "615#6000000000000000",
    "615#7000000000000000",
    "615#2B17100064000000",
    "595#6017100000000000",
    "595#4B17100064000000",
    "595#8000200100000206",
    "615#8000200100000205",
    "595#4F18100101000000",
    "595#43181002000E0000",
    "18EF2100#041B8000FFFFFFFF",
};

class writer {
public:
    explicit writer(std::filesystem::path root) : root_(std::move(root)) {}
    void add(const std::string& target, const std::vector<std::uint8_t>& bytes) {
        const auto dir = root_ / target;
        std::filesystem::create_directories(dir);
        const auto name = std::to_string(counts_[target]++);
        std::ofstream out(dir / name, std::ios::binary | std::ios::trunc);
        out.write(reinterpret_cast<const char*>(bytes.data()),
                  static_cast<std::streamsize>(bytes.size()));
    }
    void add_text(const std::string& target, std::string_view text) {
        add(target, std::vector<std::uint8_t>(text.begin(), text.end()));
    }

private:
    std::filesystem::path root_;
    std::map<std::string, int> counts_;
};

std::vector<std::uint8_t> node_and_frame(std::uint8_t node_byte, const can::frame& f) {
    std::vector<std::uint8_t> out{node_byte};
    put_frame(out, f);
    return out;
}

// Base64, as python-can's CSV writes data.
std::string base64(std::span<const std::uint8_t> d) {
    static constexpr char table[] =
        "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string out;
    for (std::size_t i = 0; i < d.size(); i += 3) {
        const std::uint32_t v = (std::uint32_t{d[i]} << 16) |
                                (i + 1 < d.size() ? std::uint32_t{d[i + 1]} << 8 : 0) |
                                (i + 2 < d.size() ? d[i + 2] : 0);
        out += table[(v >> 18) & 63];
        out += table[(v >> 12) & 63];
        out += i + 1 < d.size() ? table[(v >> 6) & 63] : '=';
        out += i + 2 < d.size() ? table[v & 63] : '=';
    }
    return out;
}

// take_node maps byte b to node b % 127 + 1.
constexpr std::uint8_t node_byte(unsigned node) { return static_cast<std::uint8_t>(node - 1); }

}  // namespace

int main(int argc, char** argv) {
    if (argc != 2) {
        std::fprintf(stderr, "usage: %s <output directory>\n", argv[0]);
        return 2;
    }
    writer w{std::filesystem::path(argv[1])};

    for (auto text : core_frames) {
        const auto f = can::parse_candump(text).value();
        w.add_text("candump", text);
        w.add("core_decode", node_and_frame(node_byte(0x15), f));
    }
    // Malformed text next to the good: the parser's error paths.
    for (auto text : {"615#0", "6150#00", "800#00", "20000000#00", "615#000000000000000000", "#"})
        w.add_text("candump", text);

    // The device-name upload of PK1000 section 12 ("BlinkMarine" in two segments), expedited and
    // aborted, with a small and a large buffer, report and strict.
    for (std::uint8_t mode = 0; mode < 4; ++mode) {
        std::vector<std::uint8_t> s{mode, node_byte(0x15)};
        s.insert(s.end(), {1, 0, 0, 0, 0, 0, 0, 0, 0});  // the not-started probe
        s.insert(s.end(), {0x08, 0x10, 0x00});           // address 1008h sub 0
        for (auto text : {"595#410810000B000000", "595#00426C696E6B4D61", "595#1772696E65000000"}) {
            s.push_back(1);  // an 8-byte reply on 580h + node
            const auto f = can::parse_candump(text).value();
            s.insert(s.end(), f.data().begin(), f.data().end());
        }
        w.add("sdo_upload", s);
    }

    // The manual rows, for the keypad decoder (model byte, node, frame) of every model the row
    // applies to, the encoder (model byte, node, the row's message), the candump parser, and as
    // bus logs for the session follower (model byte, node, then each frame as an arbitrary frame:
    // kind byte 0).
    std::vector<std::uint8_t> pk1000_log{0, node_byte(0x15)}, pkp_log{2, node_byte(0x15)};
    std::vector<std::uint8_t> mt_log{static_cast<std::uint8_t>(model::pkp3500mt), node_byte(0x15)};
    auto log_frame = [](std::vector<std::uint8_t>& log, const can::frame& f) {
        if (log.size() > 600) return;
        log.push_back(0);
        put_frame(log, f);
    };
    auto for_models = [](const model_set& models, auto f) {
        for (std::size_t i = 0; i < model_count; ++i)
            if (models.contains(static_cast<model>(i))) f(static_cast<model>(i));
    };
    auto model_node = [](model m, unsigned node) {
        return std::vector<std::uint8_t>{static_cast<std::uint8_t>(m), node_byte(node)};
    };
    auto add_frame = [&](std::string_view text, const model_set& models, unsigned node) {
        const auto f = can::parse_candump(text).value();
        w.add_text("candump", text);
        for_models(models, [&](model m) {
            auto d = model_node(m, node);
            put_frame(d, f);
            w.add("decode", d);
        });
        return f;
    };
    auto add_message = [&](const model_set& models, unsigned node, const message& msg) {
        for_models(models, [&](model m) {
            auto e = model_node(m, node);
            put_any(e, msg);
            w.add("encode", e);
        });
    };
    // A row goes into the log when it is for node 15h and for the log's model (its first byte).
    auto add_table = [&](const auto& rows, std::vector<std::uint8_t>* log) {
        for (const auto& r : rows) {
            const auto f = add_frame(r.frame, r.models, r.node);
            add_message(r.models, r.node, r.expected);
            if (log != nullptr && r.node == 0x15 &&
                r.models.contains(static_cast<model>(log->front())))
                log_frame(*log, f);
        }
    };
    add_table(codec_rows::core_rows, nullptr);
    add_table(pk1000_rows::rows, &pk1000_log);
    add_table(pkp_rows::rows, &pkp_log);
    add_table(si_rows::rows, &mt_log);
    add_table(si_reference_rows::rows, nullptr);
    for (const auto& r : codec_rows::core_error_rows) add_frame(r.frame, r.models, r.node);
    for (const auto& r : pk1000_rows::error_rows) add_frame(r.frame, r.models, r.node);
    for (const auto& r : pkp_rows::error_rows) add_frame(r.frame, r.models, r.node);
    for (const auto& r : si_rows::error_rows) add_frame(r.frame, r.models, r.node);
    for (const auto& r : si_rows::errata_rows) add_frame(r.frame, r.models, r.node);
    for (const auto& r : si_reference_rows::error_rows) add_frame(r.frame, r.models, r.node);
    for (const auto& r : pk1000_rows::encode_error_rows) add_message(r.models, r.node, r.msg);
    for (const auto& r : pkp_rows::encode_error_rows) add_message(r.models, r.node, r.msg);
    for (const auto& r : codec_rows::core_rows)
        w.add("core_decode", node_and_frame(node_byte(0x15), can::parse_candump(r.frame).value()));
    w.add("session", pk1000_log);
    w.add("session", pkp_log);
    w.add("session", mt_log);

    // The J1939 rows: the decoder (model byte, keypad selector, frame) with any keypad and
    // narrowed to the row's, the encoder (model byte, selector, the row's message), both for
    // every model the row applies to; the refusals likewise.
    auto j1939_models = [](const model_set& models, auto f) {
        for (std::size_t i = 0; i < j1939::model_row_count; ++i)
            if (models.contains(static_cast<model>(i))) f(static_cast<model>(i));
    };
    auto j1939_seed = [](model m, j1939::keypad_address keypad) {
        std::vector<std::uint8_t> v{static_cast<std::uint8_t>(m)};
        if (keypad) {
            v.push_back(1);
            v.push_back(*keypad);
        } else {
            v.push_back(0);
        }
        return v;
    };
    auto j1939_frame = [&](std::string_view text, const model_set& models,
                           j1939::keypad_address keypad) {
        const auto f = can::parse_candump(text).value();
        w.add_text("candump", text);
        j1939_models(models, [&](model m) {
            auto d = j1939_seed(m, keypad);
            put_frame(d, f);
            w.add("j1939_decode", d);
        });
    };
    auto j1939_message = [&](const j1939::message& msg, const model_set& models,
                             j1939::keypad_address keypad) {
        j1939_models(models, [&](model m) {
            auto e = j1939_seed(m, keypad);
            put_any(e, msg);
            w.add("j1939_encode", e);
        });
    };
    auto j1939_table = [&](const auto& rows) {
        for (const auto& r : rows) {
            j1939_frame(r.frame, r.models, std::nullopt);
            j1939_frame(r.frame, r.models, r.keypad);
            j1939_message(r.expected, r.models, std::nullopt);
        }
    };
    j1939_table(j1939_rows::pkp1600si_rows);
    j1939_table(j1939_rows::pkp2600si_rows);
    j1939_table(j1939_rows::other_rows);
    for (const auto& r : j1939_rows::error_rows) j1939_frame(r.frame, r.models, r.keypad);
    for (const auto& r : j1939_rows::encode_error_rows) j1939_message(r.msg, r.models, r.keypad);

    // One seed per core message kind: the selector, a node, zero fields.
    for (std::uint8_t which = 0; which < 13; ++which)
        w.add("core_encode", {which, node_byte(0x15), 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0});
    // The keypad encoder: each message kind with zero fields for every model, and a value that
    // is no model (the fuzzer varies the rest).
    const std::vector<std::uint8_t> zeros(40, 0);
    for (std::size_t k = 0; k < std::variant_size_v<message>; ++k) {
        for (std::size_t m = 0; m <= model_count; ++m) {
            std::vector<std::uint8_t> v{static_cast<std::uint8_t>(m), node_byte(0x15),
                                        static_cast<std::uint8_t>(k)};
            v.insert(v.end(), zeros.begin(), zeros.end());
            w.add("encode", v);
        }
    }
    // The log readers: the manual frames as each form writes them (log_asc, log_trc and
    // log_csv add the line that makes the form; see their files), and BLF recipes (log_blf.cpp).
    std::string candump_l, screen, cansend, asc = "base hex  timestamps absolute\n", trc11, trc21,
                                            csv = "arbitration_id,extended,remote,error,dlc,data\n";
    trc11 = ";$FILEVERSION=1.1\n;$STARTTIME=45000.0\n";
    trc21 = ";$FILEVERSION=2.1\n;$COLUMNS=N,O,T,B,I,d,R,L,D\n";
    int n = 0;
    for (auto text : core_frames) {
        const auto f = can::parse_candump(text).value();
        const std::string id(text.substr(0, text.find('#')));
        std::string bytes_spaced, bytes_plain;
        for (const auto b : f.data()) {
            char h[4];
            std::snprintf(h, sizeof h, "%02X", b);
            bytes_spaced += std::string(bytes_spaced.empty() ? "" : " ") + h;
            bytes_plain += h;
        }
        const std::string time = "1700000000." + std::to_string(100000 + n * 1000);
        candump_l += "(" + time + ") can0 " + std::string(text) + "\n";
        screen += "  can0  " + id + "   [" + std::to_string(f.size()) + "]  " + bytes_spaced + "\n";
        cansend += std::string(text) + "\n";
        const std::string x = f.is_extended() ? "x" : "";
        asc += "   " + std::to_string(n) + ".500000 1  " + id + x + "             Rx   d " +
               std::to_string(f.size()) + " " + bytes_spaced + "\n";
        trc11 += "     " + std::to_string(n + 1) + ")  " + std::to_string(n * 100) + ".0  Rx  " +
                 std::string(8 - std::min<std::size_t>(id.size(), 8), ' ') + id + "  " +
                 std::to_string(f.size()) + "  " + bytes_spaced + "\n";
        trc21 += "      " + std::to_string(n + 1) + "      " + std::to_string(n * 100) +
                 ".250 DT  1     " + id + " Rx -  " + std::to_string(f.size()) + "    " +
                 bytes_spaced + "\n";
        csv += time + ",0x" + id + "," + (f.is_extended() ? "1" : "0") + ",0,0," +
               std::to_string(f.size()) + "," + base64(f.data()) + "\n";
        ++n;
    }
    w.add_text("log_candump", candump_l);
    w.add_text("log_candump", screen);
    w.add_text("log_candump", cansend);
    w.add_text("log_candump", "615#R\n615##1000102030405060708090A0B\n(1) can0 20000080#00\n");
    w.add_text(
        "log_asc",
        asc +
            "   9.000000 1  ErrorFrame\n   9.500000 CANFD   1 Rx         80"
            "                                   0 0 0  0   130000  130        0 0 0 0 0 0\n");
    w.add_text("log_asc", "base dec  timestamps absolute\n   0.5 1  405             Rx   d 1 1\n");
    w.add_text("log_trc", trc11);
    w.add_text("log_trc", trc21);
    w.add_text("log_trc", ";$FILEVERSION=1.0\n     1)       100 0195 5 09 00 00 00 12\n");
    w.add_text("log_csv", csv);
    // BLF: the writers' header, then six CAN messages of 48 bytes (op 0) put into a zlib
    // container (op 2 with bit 3: zlib; k = 288, the whole stream), the same split across a zlib
    // and a stored container (a message cut at byte 100, carried over), and nested.
    std::vector<std::uint8_t> blf{0};
    auto can_message = [&blf](std::uint32_t id, std::uint8_t dlc) {
        blf.insert(blf.end(), {0, 0, 1, 0x40, 0x42, 0x0F, 0x00});  // op, type, flags, time
        blf.insert(blf.end(), {1, 0, 0, dlc});                     // channel, flags, dlc
        for (int i = 0; i < 4; ++i) blf.push_back(static_cast<std::uint8_t>(id >> (8 * i)));
        for (std::uint8_t i = 0; i < 8; ++i)
            blf.push_back(i < dlc ? static_cast<std::uint8_t>(i + 1) : 0);
    };
    for (std::uint32_t id : {0x000u, 0x195u, 0x215u, 0x615u, 0x595u, 0x715u}) can_message(id, 5);
    auto whole = blf;
    whole.insert(whole.end(), {2 | 8, 0x20, 0x01});
    w.add("log_blf", whole);
    auto split = blf;
    split.insert(split.end(), {2 | 8, 100, 0});
    split.insert(split.end(), {2, 188, 0});
    w.add("log_blf", split);
    auto nested = blf;
    nested.insert(nested.end(), {5 | 8, 0x20, 0x01});
    w.add("log_blf", nested);

    // The behaviour layer: a PK1000 and a PKP-2400 powered on, the bus run 40 times 50 ms, key 3
    // pressed and held, a fault, a reboot (fuzz/behaviour.cpp reads these bytes).
    for (const std::uint8_t m : {std::uint8_t{0}, static_cast<std::uint8_t>(model::pkp2400)}) {
        std::vector<std::uint8_t> b{
            m, node_byte(0x15), 0, 1, 20, 60, 30, 2, 100, 100, 80, 50, 20, 2, 0, 4};
        for (int i = 0; i < 40; ++i) b.insert(b.end(), {0, 50});
        b.insert(b.end(), {4, 3});  // press key 3
        for (int i = 0; i < 40; ++i) b.insert(b.end(), {0, 50});
        b.insert(b.end(), {7, 0, 2, 2, 6, 0});  // set_led 2 green; power cycle
        for (int i = 0; i < 20; ++i) b.insert(b.end(), {0, 50});
        w.add("behaviour", b);
    }
    return 0;
}
