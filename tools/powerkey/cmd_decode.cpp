// powerkey decode: every frame of a log, in text or JSON lines, with a summary on standard error.
#include "common.hpp"
#include "json_writer.hpp"
#include "log_formats.hpp"
#include "show.hpp"

#include <nlohmann/json.hpp>
#include <powerkey/canopen/cob_id.hpp>
#include <powerkey/j1939/id.hpp>
#include <powerkey/session.hpp>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <array>
#include <cerrno>
#include <cstring>
#include <map>
#include <string>
#include <vector>

namespace tool {
namespace {
using namespace powerkey;
using namespace std::string_view_literals;

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

void write_generic_fields(json::object_writer& w, const can::frame& f, const session_event& e) {
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

struct counts {
    std::size_t frames = 0;
    std::size_t decoded = 0;
    std::size_t foreign = 0;  // other nodes' frames, and frames no keypad sends or receives
    std::map<std::string_view, std::size_t> refused;  // keypad frames the decoder refused
    std::array<std::size_t, 128> per_node{};          // frames of per-node COB-IDs, by node
    std::size_t bad_lines = 0;
    std::array<std::size_t, logs::skip_kinds> skipped{};
    [[nodiscard]] std::size_t refused_total() const {
        std::size_t n = 0;
        for (const auto& [k, v] : refused) n += v;
        return n;
    }
};

// --- one decoding pass --------------------------------------------------------------------------

class decoder {
public:
    decoder(const options& o, model m)
        : o_(o), session_(m, o.node), picture_(m), tty_(isatty(1) != 0) {}

    void frame(const logs::record& r) {
        ++counts_.frames;
        if (o_.parse_only) return;
        const auto e = session_.step(r.frame);
        const bool pkp_j1939 = !e.decoded && e.cls.fn == canopen::function::j1939 &&
                               !info(session_.model()).value().j1939;
        const bool foreign = pkp_j1939 || (!e.decoded && e.decoded.error() == errc::wrong_id &&
                                           !concerns(e.cls, e.node));
        if (e.cls.node != 0 && e.cls.node < 128) ++counts_.per_node[e.cls.node];
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
        if (o_.json && o_.nlohmann_writer)
            nlohmann_line(out, r, e, pkp_j1939);
        else if (o_.json)
            json_line(out, r, e, pkp_j1939);
        else
            text_line(out, r, e, foreign, pkp_j1939);
        out += '\n';
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
                   bool pkp_j1939) {
        const auto n = node_of(e);
        // The common head, "(time) can0 215#0000010000000008       node 15h  ", in one append
        // (the appends are what the text output costs); escaped text takes the slow path.
        char head[128];
        std::size_t k = 0;
        auto put = [&](std::string_view t) {
            for (char c : t) head[k++] = c;
        };
        const bool fast =
            r.time.size() <= 32 && r.interface.size() <= 16 && plain(r.time) && plain(r.interface);
        if (fast) {
            if (!r.time.empty()) {
                head[k++] = '(';
                put(r.time);
                put(") ");
            }
            if (!r.interface.empty()) {
                put(r.interface);
                head[k++] = ' ';
            }
        } else {
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
        const auto frame_start = k;
        const int id_digits = r.frame.is_extended() ? 8 : 3;
        for (int i = id_digits - 1; i >= 0; --i)
            head[k++] = upper_hex[(r.frame.raw_id() >> (4 * i)) & 15];
        head[k++] = '#';
        for (auto b : r.frame.data()) {
            head[k++] = upper_hex[b >> 4];
            head[k++] = upper_hex[b & 15];
        }
        while (k - frame_start < 25) head[k++] = ' ';
        put("  ");
        if (e.decoded) {
            out.append(head, k);
            // describe()'s text, "node 15h  LED on  red: 17 ...", is the message part
            append_message_text(out, *e.decoded, canopen::node_id::make(n).value_or(e.node));
        } else {
            out.append(head, k);
        }
        if (e.decoded) {
            // the message is written above
        } else if (pkp_j1939) {
            out += "j1939  not a frame of a "sv;
            out += to_string(session_.model());
            out += " (it has no J1939)"sv;
        } else if (foreign && e.cls.fn == canopen::function::other) {
            out += "unknown frame: no keypad uses COB-ID "sv;
            append_hex_h(out, r.frame.raw_id(), 3);
        } else if (foreign) {
            out += "node "sv;
            append_hex_h(out, n, 2);
            out += "  "sv;
            out += to_string(e.cls.fn);
            out += "  another node's frame (keypad is "sv;
            append_hex_h(out, e.node.value(), 2);
            out += ')';
        } else {
            out += "node "sv;
            append_hex_h(out, n, 2);
            out += "  "sv;
            out += to_string(e.cls.fn);
            out += "  error: "sv;
            out += to_string(e.decoded.error());
        }
        if (e.sdo == sdo_pairing::reply) {
            out += "  [reply to "sv;
            append_hex_h(out, e.request.index, 4);
            out += " sub "sv;
            append_decimal(out, e.request.subindex);
            out += ']';
        } else if (e.sdo == sdo_pairing::unanswered) {
            out += "  [reply to no request]"sv;
        }
        if (e.upload_done) {
            out += "  [text: \""sv;
            append_escaped(out, session_.text(), 64);
            out += "\"]"sv;
        }
        if (e.upload_error != errc{}) {
            out += "  [upload failed: "sv;
            out += to_string(e.upload_error);
            out += ']';
        }
        if (e.new_node) {
            out += "  [node id now "sv;
            append_hex_h(out, e.new_node->value(), 2);
            out += ']';
        }
        if (e.new_protocol && e.decoded) {
            out += "  [protocol now "sv;
            out += to_string(*e.new_protocol);
            out += ']';
        }
    }

    void json_line(std::string& out, const logs::record& r, const session_event& e,
                   bool pkp_j1939) {
        json::object_writer w(out);
        if (!r.time.empty()) w.field("time", r.time);
        if (!r.interface.empty()) w.field("interface", r.interface);
        w.key("id");
        out += '"';
        append_hex(out, r.frame.raw_id(), r.frame.is_extended() ? 8 : 3);
        out += '"';
        w.field_bool("ext", r.frame.is_extended());
        w.key("data");
        out += '"';
        append_hex_bytes(out, r.frame.data().data(), r.frame.data().size());
        out += '"';
        w.field("function", to_string(e.cls.fn));
        w.field("node", node_of(e));
        w.field("model", to_string(session_.model()));
        if (e.decoded) {
            w.field("kind", kind_of(*e.decoded));
            w.key("fields");
            json::object_writer fw(out);
            for_each_field(*e.decoded, [&fw](std::string_view name, const auto& v) {
                fw.key(name);
                write_json_value(fw, v);
            });
            fw.close();
        }
        write_generic_fields(w, r.frame, e);
        if (e.sdo != sdo_pairing::none) w.field("sdo", to_string(e.sdo));
        if (e.upload_done) w.field("text", session_.text());
        if (e.upload_error != errc{}) w.field("upload_error", to_string(e.upload_error));
        if (e.new_node) w.field("new_node", e.new_node->value());
        if (e.new_protocol && !pkp_j1939 && e.decoded)
            w.field("protocol", to_string(*e.new_protocol));
        if (!e.decoded) w.field("error", to_string(e.decoded.error()));
        w.close();
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
                       bool pkp_j1939) {
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
        }
        if (e.sdo != sdo_pairing::none) j["sdo"] = std::string(to_string(e.sdo));
        if (e.upload_done) j["text"] = std::string(session_.text());
        if (e.new_node) j["new_node"] = e.new_node->value();
        if (e.new_protocol && !pkp_j1939 && e.decoded)
            j["protocol"] = std::string(to_string(*e.new_protocol));
        if (!e.decoded) j["error"] = std::string(to_string(e.decoded.error()));
        out += j.dump(-1, ' ', false, nlohmann::ordered_json::error_handler_t::replace);
    }

    const options& o_;
    session<256> session_;
    keypad_picture picture_;
    bool tty_;
    bool shown_ = false;
    counts counts_;
    output out_;
};

// --- reading the inputs
// ---------------------------------------------------------------------------

// Turns a reader's findings into at most a few lines per kind of problem, and one clear message
// for a file that is not a log at all.
template <class OnFrame>
class file_sink final : public logs::sink {
public:
    file_sink(std::string label, OnFrame on_frame, output& out)
        : label_(std::move(label)), on_frame_(on_frame), out_(out) {}

    void frame(const logs::record& r) override {
        if (!any_frame_) {
            any_frame_ = true;
            for (const auto& h : held_) emit(h);
            held_.clear();
        }
        on_frame_(r);
    }
    void problem(std::size_t line, std::string_view why, std::string_view text) override {
        ++problems_;
        if (++by_why_[why] > shown_per_kind) return;
        std::string m = label_ + ":" + std::to_string(line) + ": " + std::string(why);
        if (!text.empty()) m += ": '" + escape(text, 60) + "'";
        if (any_frame_)
            emit(m);
        else
            held_.push_back(std::move(m));
    }

    // At the end of the file: the counts of what was not shown, or the one message.
    void finish(const logs::reader& r, counts& c) {
        c.bad_lines += problems_;
        for (std::size_t k = 0; k < logs::skip_kinds; ++k) {
            const auto s = static_cast<logs::skip>(k);
            const auto n = r.skipped(s);
            c.skipped[k] += n;
            if (n == 0) continue;
            out_.flush();
            report(label_,
                   std::to_string(n) + " " + std::string(to_string(s)) + (n == 1 ? "" : "s") +
                       " not decoded (not supported by powerkey), the first at line " +
                       std::to_string(r.first_skipped(s)),
                   false);
        }
        if (r.detected() == logs::format::not_a_log) {
            out_.flush();
            report(label_, "looks like " + r.looks_like() + ", not a CAN log powerkey reads; " +
                               advice(r.looks_like()));
            return;
        }
        if (!any_frame_ && problems_ > 0) {
            out_.flush();
            std::string first = held_.empty() ? std::string() : held_.front();
            if (first.starts_with(label_ + ":")) first.erase(0, label_.size() + 1);
            report(label_, "no line is a CAN frame powerkey reads (line " + first +
                               "); it reads candump and cansend lines, Vector ASC, PEAK TRC, "
                               "python-can CSV and Vector BLF (powerkey help lists the forms)");
            return;
        }
        for (const auto& [why, n] : by_why_)
            if (n > shown_per_kind) {
                out_.flush();
                report(label_, std::to_string(n - shown_per_kind) + " more lines like that (" +
                                   std::string(why) + ")");
            }
    }

private:
    static constexpr std::size_t shown_per_kind = 3;
    static std::string advice(std::string_view looks) {
        if (looks.find("pcap") != std::string_view::npos)
            return "record the bus with candump -l, or export the capture's CAN frames as a "
                   "candump log";
        if (looks.find("MDF") != std::string_view::npos)
            return "export it as Vector ASC or BLF (CANoe, asammdf)";
        if (looks.find("gzip") != std::string_view::npos)
            return "unpack it: zcat FILE | powerkey decode";
        if (looks.find("zip") != std::string_view::npos) return "unpack it first";
        if (looks.find("JSON") != std::string_view::npos)
            return "powerkey encode --json reads JSON lines";
        return "it reads candump and cansend lines, Vector ASC, PEAK TRC, python-can CSV and "
               "Vector BLF";
    }
    void emit(const std::string& m) {
        out_.flush();
        report("", m);
    }

    std::string label_;
    OnFrame on_frame_;
    output& out_;
    bool any_frame_ = false;
    std::size_t problems_ = 0;
    std::map<std::string_view, std::size_t> by_why_;
    std::vector<std::string> held_;
};

// Reads every input, calling on_frame for each frame. Live inputs (pipes, terminals) are read as
// the bytes come, and the output is flushed after each read.
template <class OnFrame>
void read_inputs(const options& o, output& out, counts& c, OnFrame on_frame) {
    std::vector<std::string> files = o.args;
    if (files.empty()) files.push_back("-");
    std::vector<char> buf(1u << 16);
    for (const auto& path : files) {
        const auto label = file_label(path);
        const int fd = path == "-" ? 0 : ::open(path.c_str(), O_RDONLY);
        if (fd < 0) {
            out.flush();
            report(label, std::strerror(errno));
            continue;
        }
        struct stat st {};
        const bool live = ::fstat(fd, &st) != 0 || !S_ISREG(st.st_mode) || isatty(1) != 0;
        file_sink sink(label, on_frame, out);
        logs::reader reader(sink);
        for (;;) {
            const auto n = ::read(fd, buf.data(), buf.size());
            if (n < 0 && errno == EINTR) continue;
            if (n < 0) {
                out.flush();
                report(label, std::strerror(errno));
                break;
            }
            if (n == 0) break;
            reader.feed({buf.data(), static_cast<std::size_t>(n)});
            if (live) out.flush();
        }
        reader.finish();
        sink.finish(reader, c);
        if (fd != 0) ::close(fd);
    }
}

// --- --model auto
// -----------------------------------------------------------------------------------

struct stored {
    can::frame frame;
    std::string time;
    std::string interface;
    std::size_t line;
};

// Picks the model the log shows: the model string the keypad reported (100Bh, PKP 6100h sub 2:
// model_from_report), or a model name in any text it sent (device name upload); else the model
// that refuses fewest of the keypad's frames (a key or LED map wider than a model's is refused
// by it), the narrowest such model first. Says why on standard error.
model choose_model(const options& o, const std::vector<stored>& log) {
    struct score {
        model m;
        std::size_t refused = 0;
        std::string named;
    };
    std::vector<score> scores;
    for (const auto m : enum_values<model>()) {
        score sc{m, 0, {}};
        session<256> s(m, o.node);
        for (const auto& r : log) {
            const auto e = s.step(r.frame);
            if (!e.decoded && e.decoded.error() != errc::wrong_id &&
                e.cls.fn != canopen::function::j1939)
                ++sc.refused;
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

void summary(const options& o, const counts& c, model m) {
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
    if (c.bad_lines > 0)
        s += "; " + std::to_string(c.bad_lines) + (c.bad_lines == 1 ? " bad line" : " bad lines");
    for (std::size_t k = 0; k < logs::skip_kinds; ++k)
        if (c.skipped[k] > 0)
            s += "; " + std::to_string(c.skipped[k]) + " " +
                 std::string(to_string(static_cast<logs::skip>(k))) +
                 (c.skipped[k] == 1 ? " skipped" : "s skipped");
    report("summary", s, false);
    if (o.parse_only) return;
    // A log that decodes badly under the model: say what to try.
    const auto refused = c.refused_total();
    const auto keypad = c.decoded + refused;
    if (refused >= 3 && refused * 5 >= keypad) {
        std::string h = std::to_string(refused) + " of " + std::to_string(keypad) +
                        " keypad frames refused as " + std::string(to_string(m)) + " frames; ";
        h += o.model_auto ? "no model reads this log well: check --node"
                          : "if the keypad is another model, try --model auto (or --model " +
                                model_names() + ")";
        report("hint", h, false);
    }
    std::size_t top = 0;
    for (std::size_t n = 1; n < 128; ++n)
        if (c.per_node[n] > c.per_node[top]) top = n;
    if (top != 0 && top != o.node.value() && keypad * 4 < c.frames &&
        c.per_node[top] * 2 > c.frames) {
        std::string h = "most frames are of node ";
        append_hex_h(h, top, 2);
        h += ", not of keypad ";
        append_hex_h(h, o.node.value(), 2);
        h += ": try --node ";
        append_hex_h(h, top, 2);
        report("hint", h, false);
    }
}

}  // namespace

int run_decode(const options& o) {
    model m = o.keypad;
    counts read_counts;
    std::vector<stored> log;
    if (o.model_auto) {
        output none;
        read_inputs(o, none, read_counts, [&](const logs::record& r) {
            log.push_back({r.frame, std::string(r.time), std::string(r.interface), r.line});
        });
        m = choose_model(o, log);
    }
    decoder d(o, m);
    if (o.model_auto) {
        for (const auto& r : log) d.frame({r.frame, r.time, r.interface, r.line});
        d.stats().bad_lines = read_counts.bad_lines;
        d.stats().skipped = read_counts.skipped;
    } else {
        read_inputs(o, d.out(), d.stats(), [&d](const logs::record& r) { d.frame(r); });
    }
    d.out().flush();
    summary(o, d.stats(), m);
    return failures == 0 ? 0 : 1;
}

}  // namespace tool
