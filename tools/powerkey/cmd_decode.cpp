// powerkey decode: every frame of a log, in text or JSON lines, with a summary on standard error.
#include "cli.hpp"
#include "commands.hpp"
#include "field_value.hpp"
#include "input.hpp"
#include "json_writer.hpp"
#include "show.hpp"

#include <nlohmann/json.hpp>
#include <powerkey/canopen/cob_id.hpp>
#include <powerkey/j1939/id.hpp>
#include <powerkey/session.hpp>

#include <unistd.h>

#include <array>
#include <charconv>
#include <cstring>
#include <map>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace tool {
namespace {
using namespace powerkey;
using namespace std::string_view_literals;

struct decode_options {
    bool json = false;
    bool show = false;
    bool strict = false;  // only the manual's form (docs/decoder.md, "Tolerant and strict reading")
    // For the benchmark (scripts/bench_cli.sh): read and parse only, or decode without output.
    bool parse_only = false;
    bool quiet = false;
    bool nlohmann_writer = false;  // decode --json through nlohmann::json (for the benchmark)
    std::vector<std::string> files;
};

// --- the frame's own part of a line
// ---------------------------------------------------------------

void append_untrusted(std::string& out, std::string_view s, std::size_t max) {
    if (s.size() <= max && plain(s))
        out += s;
    else
        append_escaped(out, s, max);
}

// The node a frame belongs to: the node of its COB-ID, or the keypad followed for the others.
std::uint8_t node_of(const session_event& e) {
    return e.cls.node != 0 ? e.cls.node : e.node.value();
}

template <class Writer>
void write_generic_fields(Writer& w, const can::frame& f, const session_event& e) {
    switch (e.cls.fn) {
        case canopen::function::nmt:
            if (const auto m = canopen::decode_nmt(f)) {
                w.field("command", to_string(m->command));
                w.field("target", m->target.value());
            }
            break;
        case canopen::function::heartbeat:
            if (const auto m = canopen::decode_heartbeat(f, e.node))
                w.field("state", to_string(m->state));
            break;
        case canopen::function::sdo_rx:
        case canopen::function::sdo_tx: {
            const auto n = canopen::node_id::make(e.cls.node).value();
            bool carries = false;
            if (e.cls.fn == canopen::function::sdo_rx) {
                const auto r = canopen::decode_sdo_request(f, n);
                carries = r && !std::holds_alternative<canopen::sdo_segment_request>(*r);
            } else {
                const auto r = canopen::decode_sdo_response(f, n);
                carries = r && !std::holds_alternative<canopen::sdo_segment_response>(*r);
            }
            if (carries) {
                w.field("index", static_cast<std::uint64_t>(f[1] | (f[2] << 8)));
                w.field("subindex", f[3]);
            }
            break;
        }
        case canopen::function::j1939: {
            const auto id = j1939::parse_id(f).value();
            w.field("priority", id.priority.value());
            w.field("pgn", id.pgn.value());
            w.field("source", id.source);
            w.field("destination", id.destination);
            break;
        }
        default: break;
    }
}

// --- counting -----------------------------------------------------------------------------------

// A 29-bit frame the J1939 codec calls wrong_id: another PGN (not a keypad frame), or, narrowed by
// --address, another keypad's.
template <class Event>
bool is_j1939_foreign(const Event& e) {
    return !e.decoded && e.cls.fn == canopen::function::j1939 &&
           e.decoded.error() == errc::wrong_id;
}

// The keypad a J1939 message concerns (j1939::keypad_address_of); nullopt for a CANopen message.
std::optional<std::uint8_t> j1939_keypad_of(const message& msg) {
    return visit_message(msg, [](const auto& s) -> std::optional<std::uint8_t> {
        using S = std::remove_cvref_t<decltype(s)>;
        if constexpr (powerkey::j1939::message_alternative<S>)
            return powerkey::j1939::keypad_address_of(s);
        else
            return std::nullopt;
    });
}

// A frame that is none of the keypad's: the J1939 ones above, and wrong_id on a COB-ID that does
// not concern the keypad's node (another node's, or no keypad function). Every other frame the
// decoder refuses is a refused keypad frame: the summary and --model auto count the same ones.
template <class Event>
bool is_foreign(const Event& e) {
    return is_j1939_foreign(e) ||
           (!e.decoded && e.decoded.error() == errc::wrong_id && !concerns(e.cls, e.node));
}

struct counts {
    std::size_t frames = 0;
    std::size_t decoded = 0;
    std::size_t foreign = 0;  // other nodes' frames, and frames no keypad sends or receives
    std::map<std::string_view, std::size_t> refused;  // keypad frames the decoder refused
    std::array<std::size_t, 128> per_node{};          // frames of per-node COB-IDs, by node
    // Under --address, the J1939 frames of other keypads, by the keypad's address (its own
    // frames' source, its commands' destination): for the hint to try another --address.
    std::array<std::size_t, 256> per_address{};
    input_counts read;  // lines and frames the readers passed over
    [[nodiscard]] std::size_t refused_total() const {
        std::size_t n = 0;
        for (const auto& [k, v] : refused) n += v;
        return n;
    }
};

// --- one decoding pass --------------------------------------------------------------------------

class decoder final : public frame_handler {
public:
    decoder(const options& c, const decode_options& o, model m, output& out)
        : o_(o),
          session_(m, c.node, o.strict ? reading::strict : reading::tolerant),
          model_(m),
          address_(c.address),
          picture_(m),
          tty_(isatty(1) != 0),
          out_(out) {
        session_.narrow_j1939(c.address);
    }

    void frame(const logs::record& r) override {
        ++counts_.frames;
        if (o_.parse_only) return;
        const auto e = session_.step(r.frame);
        const bool j1939_foreign = is_j1939_foreign(e);
        const bool foreign = is_foreign(e);
        if (e.cls.node != 0 && e.cls.node < 128) ++counts_.per_node[e.cls.node];
        if (j1939_foreign && address_)  // whose frame it is, decoded for any keypad
            if (const auto any = decode(r.frame, e.node, model_))
                if (const auto a = j1939_keypad_of(*any)) ++counts_.per_address[*a];
        if (e.decoded)
            ++counts_.decoded;
        else if (foreign)
            ++counts_.foreign;
        else
            ++counts_.refused[to_string(e.decoded.error())];
        if (o_.quiet) return;
        std::string& out = out_.buffer();
        const bool picture = o_.show && e.decoded && picture_.update(*e.decoded);
        if (o_.show && tty_ && shown_)
            out += "\x1b[1A\r\x1b[2K"sv;  // the picture stays at the bottom
        if (o_.json && o_.nlohmann_writer) {
            nlohmann_line(out, r, e, j1939_foreign);
            out += '\n';
        } else if (o_.json) {
            json_line(out, r, e, j1939_foreign);  // with its line end
        } else {
            text_line(out, r, e, foreign, j1939_foreign);  // with its line end
        }
        if (o_.show && (picture || (tty_ && shown_))) {
            out += picture_.draw();
            shown_ = true;
        }
        out_.maybe_flush();
    }

    output& out() { return out_; }
    counts& stats() { return counts_; }
    [[nodiscard]] model keypad() const { return session_.model(); }

private:
    void text_line(std::string& out, const logs::record& r, const session_event& e, bool foreign,
                   bool j1939_foreign) {
        const auto n = node_of(e);
        const bool fast =
            r.time.size() <= 32 && r.interface.size() <= 16 && plain(r.time) && plain(r.interface);
        if (!fast) {  // escaped text, before the line buffer takes the rest
            if (!r.time.empty()) {
                out += '(';
                append_untrusted(out, r.time, 32);
                out += ") "sv;
            }
            if (!r.interface.empty()) {
                append_untrusted(out, r.interface, 16);
                out += ' ';
            }
        }
        // The line in a stack buffer, appended once (the appends are what the output costs):
        // "(time) can0 215#0000010000000008       node 15h  ..."
        line_out line(out);
        line.put_with(128, [&](char* head) {
            std::size_t k = 0;
            auto put = [&](std::string_view t) {
                std::memcpy(head + k, t.data(), t.size());
                k += t.size();
            };
            if (fast && !r.time.empty()) {
                head[k++] = '(';
                put(r.time);
                put(") ");
            }
            if (fast && !r.interface.empty()) {
                put(r.interface);
                head[k++] = ' ';
            }
            const auto frame_start = k;
            const int id_digits = r.frame.is_extended() ? 8 : 3;
            for (int i = id_digits - 1; i >= 0; --i)
                head[k++] = upper_hex[(r.frame.raw_id() >> (4 * i)) & 15];
            head[k++] = '#';
            for (auto b : r.frame.data()) {
                head[k++] = upper_hex[b >> 4];
                head[k++] = upper_hex[b & 15];
            }
            if (k - frame_start < 25) {
                std::memset(head + k, ' ', 25 - (k - frame_start));
                k = frame_start + 25;
            }
            put("  ");
            return k;
        });
        const auto hex_h = [&line](std::uint64_t v, int digits) {
            line.put_with(18, [&](char* p) {
                for (int i = 0; i < digits; ++i)
                    p[i] = upper_hex[(v >> (4 * (digits - 1 - i))) & 15];
                p[digits] = 'h';
                return static_cast<std::size_t>(digits) + 1;
            });
        };
        if (e.decoded) {
            // describe()'s text, "node 15h  LED on  red: 17 ...", is the message part;
            // description_capacity characters hold every message
            constexpr std::size_t cap = description_capacity;
            line.put_with(cap, [&](char* p) -> std::size_t {
                const auto text = describe(*e.decoded, canopen::node_id::make(n).value_or(e.node),
                                           std::span<char>(p, cap));
                return text ? text->size() : cap;
            });
        } else if (j1939_foreign) {
            const auto id = j1939::parse_id(r.frame).value();
            if (j1939::is_keypad_pgn(id.pgn)) {
                line.put("j1939  another keypad's frame (keypad is "sv);
                hex_h(session_.j1939_address(), 2);
                line.put(')');
            } else {
                line.put("j1939  not a keypad frame (PGN "sv);
                hex_h(id.pgn.value(), id.pgn.value() > 0xFFFF ? 5 : 4);
                line.put(')');
            }
        } else if (foreign && e.cls.fn == canopen::function::other) {
            line.put("unknown frame: no keypad uses COB-ID "sv);
            hex_h(r.frame.raw_id(), 3);
        } else if (foreign) {
            line.put("node "sv);
            hex_h(n, 2);
            line.put("  "sv);
            line.put(to_string(e.cls.fn));
            line.put("  another node's frame (keypad is "sv);
            hex_h(e.node.value(), 2);
            line.put(')');
        } else if (e.cls.fn == canopen::function::j1939) {  // no node: "j1939  error: ..."
            line.put("j1939  error: "sv);
            line.put(to_string(e.decoded.error()));
        } else {
            line.put("node "sv);
            hex_h(n, 2);
            line.put("  "sv);
            line.put(to_string(e.cls.fn));
            line.put("  error: "sv);
            line.put(to_string(e.decoded.error()));
        }
        if (e.sdo == sdo_pairing::reply) {
            line.put("  [reply to "sv);
            hex_h(e.request.index, 4);
            line.put(" sub "sv);
            line.put_with(3, [&](char* p) {
                return static_cast<std::size_t>(std::to_chars(p, p + 3, e.request.subindex).ptr -
                                                p);
            });
            line.put(']');
        } else if (e.sdo == sdo_pairing::unanswered) {
            line.put("  [reply to no request]"sv);
        }
        if (e.upload_done) {
            line.put("  [text: \""sv);
            line.put(escape(session_.text(), 64));
            line.put("\"]"sv);
        }
        if (e.upload_error != errc{}) {
            line.put("  [upload failed: "sv);
            line.put(to_string(e.upload_error));
            line.put(']');
        }
        if (e.new_node) {
            line.put("  [node id now "sv);
            hex_h(e.new_node->value(), 2);
            line.put(']');
        }
        if (e.new_protocol && e.decoded) {
            line.put("  [protocol now "sv);
            line.put(to_string(*e.new_protocol));
            line.put(']');
        }
        if (e.new_address) {
            line.put("  [J1939 address now "sv);
            hex_h(*e.new_address, 2);
            line.put(']');
        }
        line.put('\n');
    }

    void json_line(std::string& out, const logs::record& r, const session_event& e,
                   bool j1939_foreign) {
        json::line_out line(out);  // the line in a stack buffer: one append to `out`
        json::basic_object_writer w(line);
        if (!r.time.empty()) w.field("time", r.time);
        if (!r.interface.empty()) w.field("interface", r.interface);
        w.key("id");
        const int id_digits = r.frame.is_extended() ? 8 : 3;
        const auto data = r.frame.data();
        line.put_with(2 + 8 + 8 + 2 + 16 + 1, [&](char* p) {
            std::size_t n = 0;
            p[n++] = '"';
            for (int i = id_digits - 1; i >= 0; --i)
                p[n++] = upper_hex[(r.frame.raw_id() >> (4 * i)) & 15];
            p[n++] = '"';
            return n;
        });
        w.field_bool("ext", r.frame.is_extended());
        w.key("data");
        line.put_with(2 + 16, [&](char* p) {
            std::size_t n = 0;
            p[n++] = '"';
            for (const auto b : data) {
                p[n++] = upper_hex[b >> 4];
                p[n++] = upper_hex[b & 15];
            }
            p[n++] = '"';
            return n;
        });
        w.field("function", to_string(e.cls.fn));
        w.field("node", node_of(e));
        w.field("model", to_string(session_.model()));
        if (e.decoded) {
            w.field("kind", kind_of(*e.decoded));
            w.key("fields");
            json::basic_object_writer fw(line);
            for_each_field(*e.decoded, [&fw](std::string_view name, const auto& v) {
                fw.key(name);
                write_json_value(fw, v);
            });
            fw.close();
            // Only a frame not in the manual's form says so (docs/decoder.md).
            if (const auto form = form_of(*e.decoded); form != frame_form::manual)
                w.field("form", to_string(form));
        }
        write_generic_fields(w, r.frame, e);
        if (e.sdo != sdo_pairing::none) w.field("sdo", to_string(e.sdo));
        if (e.upload_done) w.field("text", session_.text());
        if (e.upload_error != errc{}) w.field("upload_error", to_string(e.upload_error));
        if (e.new_node) w.field("new_node", e.new_node->value());
        if (e.new_protocol && !j1939_foreign && e.decoded)
            w.field("protocol", to_string(*e.new_protocol));
        if (e.new_address) w.field("new_address", *e.new_address);
        if (!e.decoded) w.field("error", to_string(e.decoded.error()));
        w.close();
        line.put('\n');
    }

    // The same line through nlohmann::ordered_json, for the writer comparison of
    // docs/performance.md (decode --json --nlohmann-writer; scripts/bench_cli.sh).
    template <class T>
    static nlohmann::ordered_json json_value(const T& v) {
        if constexpr (std::is_same_v<T, bool>) {
            return v;
        } else if constexpr (std::is_enum_v<T>) {
            if (is_named(v)) return std::string(to_string(v));
            return static_cast<std::uint64_t>(v);
        } else if constexpr (is_index_set<T>::value) {
            auto a = nlohmann::ordered_json::array();
            for (unsigned i = 1; i <= T::max; ++i)
                if (v.contains(i)) a.push_back(i);
            return a;
        } else if constexpr (is_byte_array<T>::value) {
            std::string hex;
            for (auto b : v) append_hex(hex, b, 2);
            return hex;
        } else if constexpr (is_bounded<T>::value) {
            return static_cast<std::uint64_t>(v.value());
        } else {
            return static_cast<std::uint64_t>(v);
        }
    }

    void nlohmann_line(std::string& out, const logs::record& r, const session_event& e,
                       bool j1939_foreign) {
        nlohmann::ordered_json j;
        if (!r.time.empty()) j["time"] = std::string(r.time);
        if (!r.interface.empty()) j["interface"] = std::string(r.interface);
        std::string id, data;
        append_hex(id, r.frame.raw_id(), r.frame.is_extended() ? 8 : 3);
        for (auto b : r.frame.data()) append_hex(data, b, 2);
        j["id"] = id;
        j["ext"] = r.frame.is_extended();
        j["data"] = data;
        j["function"] = std::string(to_string(e.cls.fn));
        j["node"] = node_of(e);
        j["model"] = std::string(to_string(session_.model()));
        if (e.decoded) {
            j["kind"] = std::string(kind_of(*e.decoded));
            auto fields = nlohmann::ordered_json::object();
            for_each_field(*e.decoded, [&fields](std::string_view name, const auto& v) {
                fields[std::string(name)] = json_value(v);
            });
            j["fields"] = fields;
            if (const auto form = form_of(*e.decoded); form != frame_form::manual)
                j["form"] = std::string(to_string(form));
        }
        // The same generic keys as the tool's writer, through the same reader of the frame.
        struct {
            nlohmann::ordered_json& j;
            void field(std::string_view k, std::string_view v) {
                j[std::string(k)] = std::string(v);
            }
            void field(std::string_view k, std::uint64_t v) { j[std::string(k)] = v; }
        } generic{j};
        write_generic_fields(generic, r.frame, e);
        if (e.sdo != sdo_pairing::none) j["sdo"] = std::string(to_string(e.sdo));
        if (e.upload_done) j["text"] = std::string(session_.text());
        if (e.upload_error != errc{}) j["upload_error"] = std::string(to_string(e.upload_error));
        if (e.new_node) j["new_node"] = e.new_node->value();
        if (e.new_protocol && !j1939_foreign && e.decoded)
            j["protocol"] = std::string(to_string(*e.new_protocol));
        if (e.new_address) j["new_address"] = *e.new_address;
        if (!e.decoded) j["error"] = std::string(to_string(e.decoded.error()));
        out += j.dump(-1, ' ', false, nlohmann::ordered_json::error_handler_t::replace);
    }

    const decode_options& o_;
    session<256> session_;
    model model_;
    j1939::keypad_address address_;
    keypad_picture picture_;
    bool tty_;
    bool shown_ = false;
    counts counts_;
    output& out_;
};

// --- --model auto
// -----------------------------------------------------------------------------------

// What --model auto keeps of a frame until it has chosen the model: the frame, its line, and its
// time and interface as offsets into one string of text.
struct kept_frame {
    can::frame frame;
    std::uint32_t time_at, time_size, interface_at, interface_size;
    std::size_t line;
};

// Picks the model the log shows: the model string the keypad reported (100Bh, PKP 6100h sub 2:
// model_from_report), or a model name in any text it sent (device name upload); else the model
// that refuses fewest of the keypad's frames (a key or LED map wider than a model's is refused
// by it), the narrowest such model first. Says why on standard error.
model choose_model(const options& o, const std::vector<kept_frame>& log) {
    struct score {
        model m;
        std::size_t refused = 0;
        std::string named;
    };
    std::vector<score> scores;
    for (const auto m : enum_values<model>()) {
        score sc{m, 0, {}};
        session<256> s(m, o.node);
        s.narrow_j1939(o.address);
        for (const auto& r : log) {
            const auto e = s.step(r.frame);
            // As the summary counts: a J1939 frame counts as a CANopen one (the J1939 row of a
            // model refuses a key or LED it lacks, a frame its manual does not have or no source
            // shows), and a PDO of the keypad's node that the model lacks (wrong_id) is refused.
            if (!e.decoded && !is_foreign(e)) ++sc.refused;
            if (e.upload_done && sc.named.empty()) {
                std::string_view t = s.text();
                if (const auto reported = model_from_report(t); reported && *reported == m)
                    sc.named = t;
                // "PKP-2400-LI", "BlinkMarine PK1000": any word of the text that names m
                while (sc.named.empty() && !t.empty()) {
                    const auto sp = t.find_first_of(" ,;/");
                    if (const auto named = model_from_name(t.substr(0, sp)); named && *named == m)
                        sc.named = s.text();
                    t.remove_prefix(sp == std::string_view::npos ? t.size() : sp + 1);
                }
            }
        }
        scores.push_back(sc);
    }
    auto keys = [](model m) { return info(m).value().keys; };
    const score* best = &scores.front();
    for (const auto& sc : scores)
        if (sc.refused < best->refused ||
            (sc.refused == best->refused && keys(sc.m) < keys(best->m)))
            best = &sc;
    // The keypad's own name counts unless its model refuses more of the log than another does.
    std::string named_note;
    for (const auto& sc : scores) {
        if (sc.named.empty()) continue;
        if (sc.refused <= best->refused) {
            report("--model auto",
                   std::string(to_string(sc.m)) + ": the keypad names itself \"" +
                       escape(sc.named, 40) + "\"",
                   false);
            return sc.m;
        }
        named_note = "; the keypad names itself \"" + escape(sc.named, 40) + "\" but " +
                     std::string(to_string(sc.m)) + " refuses " + std::to_string(sc.refused) +
                     " of its frames";
    }
    std::string others;
    bool all_equal = true;
    std::vector<std::string> ties;
    for (const auto& sc : scores) {
        if (sc.refused != best->refused) all_equal = false;
        if (&sc == best) continue;
        if (sc.refused == best->refused) ties.emplace_back(to_string(sc.m));
        others += (others.empty() ? "" : ", ") + std::string(to_string(sc.m)) + " " +
                  std::to_string(sc.refused);
    }
    if (all_equal) {
        report("--model auto",
               "cannot tell the model: no frame of the log decodes differently under the " +
                   std::to_string(model_count) +
                   " models (no model string, no key or LED map); decoding as pk1000, give --model",
               false);
        return model::pk1000;
    }
    std::string why = std::string(to_string(best->m)) + ": it refuses " +
                      std::to_string(best->refused) + " of the keypad's frames (" + others + ")";
    if (!ties.empty()) {
        why += "; ";
        for (std::size_t i = 0; i < ties.size(); ++i) why += (i ? ", " : "") + ties[i];
        why += " decode it as well (the narrowest is taken: no key or LED above its own seen)";
    }
    why += named_note;
    report("--model auto", why, false);
    return best->m;
}

// --- the summary ------------------------------------------------------------------------------

void summary(const options& c0, const decode_options& o, const counts& c, model m) {
    std::string s = std::to_string(c.frames) + (c.frames == 1 ? " frame" : " frames");
    if (!o.parse_only) {
        s += ": " + std::to_string(c.decoded) + " decoded, " + std::to_string(c.foreign) +
             " of other nodes or no keypad, " + std::to_string(c.refused_total()) + " refused";
        if (!c.refused.empty()) {
            s += " (";
            bool first = true;
            for (const auto& [why, n] : c.refused) {
                s += (first ? "" : ", ") + std::string(why) + " " + std::to_string(n);
                first = false;
            }
            s += ")";
        }
    }
    const auto bad = c.read.bad_lines;
    if (bad > 0) s += "; " + std::to_string(bad) + (bad == 1 ? " bad line" : " bad lines");
    for (std::size_t k = 0; k < logs::skip_kinds; ++k)
        if (const auto n = c.read.skipped[k]; n > 0)
            s += "; " + std::to_string(n) + " " +
                 std::string(to_string(static_cast<logs::skip>(k))) +
                 (n == 1 ? " skipped" : "s skipped");
    report("summary", s, false);
    if (o.parse_only) return;
    // A log that decodes badly under the model: say what to try.
    const auto refused = c.refused_total();
    const auto keypad = c.decoded + refused;
    if (refused >= 3 && refused * 5 >= keypad) {
        std::string h = std::to_string(refused) + " of " + std::to_string(keypad) +
                        " keypad frames refused as " + std::string(to_string(m)) + " frames; ";
        h += c0.model_auto ? "no model reads this log well: check --node"
                           : "if the keypad is another model, try --model auto (or --model " +
                                 model_names() + ")";
        report("hint", h, false);
    }
    std::size_t top = 0;
    for (std::size_t n = 1; n < 128; ++n)
        if (c.per_node[n] > c.per_node[top]) top = n;
    if (top != 0 && top != c0.node.value() && keypad * 4 < c.frames &&
        c.per_node[top] * 2 > c.frames) {
        std::string h = "most frames are of node ";
        append_hex_h(h, top, 2);
        h += ", not of keypad ";
        append_hex_h(h, c0.node.value(), 2);
        h += ": try --node ";
        append_hex_h(h, top, 2);
        report("hint", h, false);
    }
    // The same for --address: most frames are J1939 ones of another keypad address.
    std::size_t top_address = 0;
    for (std::size_t a = 1; a < c.per_address.size(); ++a)
        if (c.per_address[a] > c.per_address[top_address]) top_address = a;
    if (c0.address && c.per_address[top_address] > 0 && keypad * 4 < c.frames &&
        c.per_address[top_address] * 2 > c.frames) {
        std::string h = "most J1939 frames are of the keypad at ";
        append_hex_h(h, top_address, 2);
        h += ", not of keypad ";
        append_hex_h(h, *c0.address, 2);
        h += ": try --address ";
        append_hex_h(h, top_address, 2);
        report("hint", h, false);
    }
}

// --model auto: keeps the frames until it has chosen the model (at the end of the input, or when
// they fill logs::limits::model_auto_bytes), decodes them then, and the frames after them as they
// come.
class auto_decoder final : public frame_handler {
public:
    auto_decoder(const options& c, const decode_options& o, output& out)
        : c_(c), o_(o), out_(out) {}

    void frame(const logs::record& r) override {
        if (d_) return d_->frame(r);
        const auto at = text_.size();
        text_.append(r.time).append(r.interface);
        kept_.push_back({r.frame, static_cast<std::uint32_t>(at),
                         static_cast<std::uint32_t>(r.time.size()),
                         static_cast<std::uint32_t>(at + r.time.size()),
                         static_cast<std::uint32_t>(r.interface.size()), r.line});
        if (kept_.capacity() * sizeof(kept_frame) + text_.capacity() >=
            logs::limits::model_auto_bytes) {
            out_.flush();
            report("--model auto",
                   "the first " + std::to_string(kept_.size()) + " frames fill what it keeps (" +
                       std::to_string(logs::limits::model_auto_bytes >> 20) +
                       " MiB): the model is chosen from them, the rest decoded as it comes",
                   false);
            choose();
        }
    }
    // Chooses (if not yet), decodes what was kept; the decoder from then on.
    decoder& choose() {
        if (d_) return *d_;
        d_.emplace(c_, o_, choose_model(c_, kept_), out_);
        const std::string_view text = text_;
        for (const auto& k : kept_)
            d_->frame({k.frame, text.substr(k.time_at, k.time_size),
                       text.substr(k.interface_at, k.interface_size), k.line});
        kept_ = {};
        text_ = {};
        return *d_;
    }

private:
    const options& c_;
    const decode_options& o_;
    output& out_;
    std::vector<kept_frame> kept_;
    std::string text_;
    std::optional<decoder> d_;
};

int run_decode(const options& c, const decode_options& o) {
    output out;
    input_counts read_counts;
    if (c.model_auto) {
        auto_decoder a(c, o, out);
        read_inputs(o.files, a, out, read_counts);
        auto& d = a.choose();
        d.stats().read = read_counts;
        out.flush();
        summary(c, o, d.stats(), d.keypad());
        return status();
    }
    decoder d(c, o, c.keypad, out);
    read_inputs(o.files, d, out, d.stats().read);
    out.flush();
    summary(c, o, d.stats(), c.keypad);
    return status();
}

}  // namespace

void add_decode(registry& r) {
    static decode_options o;
    auto& sub = r.add(
        {"decode",
         "[--model M|auto] [--node N] [--address A] [--json | --show] [--strict] [FILE...]",
         "every frame of a bus log, in text or JSON lines",
         "  --json       JSON lines, one per frame (docs/cli.md has the schema)\n"
         "  --show       draw the keypad after each frame that changes it (not with --json)\n"
         "  --strict     refuse frames not in the manual's form (trimmed, padded) with "
         "wrong_length\n",
         model_use::or_auto},
        [&r] {
            if (o.json && o.show)
                return usage_error(
                    "--show draws pictures for people and --json writes lines for programs: use "
                    "one");
            if (o.nlohmann_writer && !o.json)
                return usage_error("--nlohmann-writer is an option of decode --json");
            return run_decode(r.common(), o);
        });
    sub.add_flag("--json", o.json);
    sub.add_flag("--show", o.show);
    sub.add_flag("--strict", o.strict);
    sub.add_flag("--parse-only", o.parse_only);
    sub.add_flag("--quiet", o.quiet);
    sub.add_flag("--nlohmann-writer", o.nlohmann_writer);
    sub.add_option("FILE", o.files);
}

}  // namespace tool
