// powerkey Wireshark plugin: registration, preferences and the dissection tree. Every decision
// about a frame (is it the keypad's, what it means, the names of fields and values) comes from
// the library through powerkey_adapter.hpp; this file only talks to Wireshark.
//
// Wireshark tries the "can.id" table first, then "Decode As", then the "can" heuristics. The
// plugin sits in "can.id" for every 11-bit identifier, so it sees each standard frame before
// the generic CANopen and AUTOSAR NM dissectors and gives back (returns 0) every frame that is
// not the keypad's; 29-bit frames reach it as a "can" heuristic (a keypad's J1939 frames, beside
// Wireshark's own J1939 dissector).
//
// The session (pairing, segmented strings, node-id changes) depends on the frames before: it is
// run on the first pass, which Wireshark makes in capture order, and its result is kept with
// each packet (p_add_proto_data, file scope), because later passes come in any order.
#include "powerkey_adapter.hpp"

#include <epan/dissectors/packet-socketcan.h>
#include <epan/expert.h>
#include <epan/packet.h>
#include <epan/prefs.h>
#include <epan/proto_data.h>
#include <epan/strutil.h>
#include <ws_symbol_export.h>
#include <wsutil/report_message.h>

#include <cstdio>
#include <cstdlib>
#include <new>
#include <optional>
#include <string>
#include <vector>

// The four symbols Wireshark looks up in a plugin (README.plugins); const needs extern in C++.
extern "C" {
WS_DLL_PUBLIC const gchar plugin_version[];
WS_DLL_PUBLIC const int plugin_want_major;
WS_DLL_PUBLIC const int plugin_want_minor;
WS_DLL_PUBLIC void plugin_register(void);
const gchar plugin_version[] = POWERKEY_PLUGIN_VERSION;
const int plugin_want_major = POWERKEY_WIRESHARK_MAJOR;
const int plugin_want_minor = POWERKEY_WIRESHARK_MINOR;
}

namespace {

int proto_powerkey = -1;
gint ett_powerkey = -1;

// The fields every frame may have; the message fields follow, one per field name.
int hf_kind = -1;
int hf_error = -1;
int hf_function = -1;
int hf_node = -1;
int hf_model = -1;
int hf_sdo_index = -1;
int hf_sdo_subindex = -1;
int hf_sdo_pairing = -1;
int hf_reply_index = -1;
int hf_reply_subindex = -1;
int hf_text = -1;
int hf_upload_error = -1;
int hf_new_node = -1;
int hf_protocol = -1;
int hf_new_address = -1;
int hf_pgn = -1;
// A frame of the keypad that the library refuses: an expert warning, besides powerkey.error.
expert_field ei_refused = EI_INIT;

// Wireshark keeps pointers into these for the life of the program: allocated once, never freed.
struct registry {
    std::vector<powerkey_ws::field_spec> catalog;
    std::vector<int> ids;  // hf id per catalog entry
    std::vector<std::string> abbrevs;
    std::vector<std::vector<value_string>> value_strings;
    std::vector<hf_register_info> hf;
    std::string model_help;  // the description of powerkey.model
};
registry* reg = nullptr;

// Preferences: powerkey.model (a name, read as the tool's --model reads it) and powerkey.node.
const char* pref_model_name = "pk1000";
gint pref_model = 0;
guint pref_node = 0x15;

// powerkey.model changed: the model it names, or a message and the model as it was.
void apply_preferences() {
    const std::string_view name = pref_model_name != nullptr ? pref_model_name : "";
    if (const auto m = powerkey_ws::model_from_name(name)) {
        pref_model = static_cast<gint>(*m);
        return;
    }
    const auto now = powerkey_ws::model_of(pref_model);
    report_failure("powerkey.model: unknown model '%s' (%s); still decoding as %s",
                   powerkey_ws::printable(name).c_str(), powerkey_ws::model_list().c_str(),
                   now ? std::string(powerkey::to_string(*now)).c_str() : "pk1000");
}

std::optional<powerkey_ws::follower> follower;

void init_capture() {
    const unsigned node = powerkey_ws::valid_node(pref_node) ? pref_node : 0x15u;
    follower.emplace(pref_model, node);
}

void cleanup_capture() { follower.reset(); }

hf_register_info make_hf(int* id, const char* name, const char* abbrev, ftenum type, int display,
                         const void* strings, const char* blurb) {
    hf_register_info r{};
    r.p_id = id;
    r.hfinfo.name = name;
    r.hfinfo.abbrev = abbrev;
    r.hfinfo.type = type;
    r.hfinfo.display = display;
    r.hfinfo.strings = strings;
    r.hfinfo.bitmask = 0;
    r.hfinfo.blurb = blurb;
    HFILL_INIT(r)
    return r;
}

// Names the generic fields use; a message field of the same name goes under powerkey.field.
bool generic_name(const std::string& name) {
    for (const char* n : {"kind", "error", "function", "node", "model", "sdo", "session", "j1939"})
        if (name == n) return true;
    return false;
}

void register_protoinfo() {
    proto_powerkey =
        proto_register_protocol("Blink Marine PowerKey keypad", "PowerKey", "powerkey");
    reg = new registry;

    static hf_register_info generic[] = {
        make_hf(&hf_kind, "Kind", "powerkey.kind", FT_STRING, BASE_NONE, nullptr,
                "The message kind, as powerkey decode --json names it"),
        make_hf(&hf_error, "Error", "powerkey.error", FT_STRING, BASE_NONE, nullptr,
                "Why the library refused a frame of the keypad (docs/errors.md)"),
        make_hf(&hf_function, "Function", "powerkey.function", FT_STRING, BASE_NONE, nullptr,
                "nmt, sync, tpdo1..tpdo4, rpdo1..rpdo4, sdo_tx, sdo_rx, heartbeat, j1939"),
        make_hf(&hf_node, "Node", "powerkey.node", FT_UINT8, BASE_HEX_DEC, nullptr,
                "The node of a per-node COB-ID, else the keypad's node id"),
        make_hf(&hf_model, "Model", "powerkey.model", FT_STRING, BASE_NONE, nullptr,
                "The keypad model the frame was decoded for"),
        make_hf(&hf_sdo_index, "SDO index", "powerkey.sdo.index", FT_UINT16, BASE_HEX, nullptr,
                "Object index of an SDO frame that carries one"),
        make_hf(&hf_sdo_subindex, "SDO sub-index", "powerkey.sdo.subindex", FT_UINT8, BASE_DEC,
                nullptr, "Object sub-index of an SDO frame that carries one"),
        make_hf(&hf_sdo_pairing, "SDO exchange", "powerkey.sdo.pairing", FT_STRING, BASE_NONE,
                nullptr, "request, reply (to the pending request) or unanswered"),
        make_hf(&hf_reply_index, "Reply to index", "powerkey.sdo.reply_to.index", FT_UINT16,
                BASE_HEX, nullptr, "The object of the request this reply answers"),
        make_hf(&hf_reply_subindex, "Reply to sub-index", "powerkey.sdo.reply_to.subindex",
                FT_UINT8, BASE_DEC, nullptr, "The sub-index of the request this reply answers"),
        make_hf(&hf_text, "Text", "powerkey.sdo.text", FT_STRING, BASE_NONE, nullptr,
                "The whole string of a segmented upload that ended with this frame"),
        make_hf(&hf_upload_error, "Upload error", "powerkey.sdo.upload_error", FT_STRING, BASE_NONE,
                nullptr, "Why a segmented upload failed with this frame"),
        make_hf(&hf_new_node, "Node id now", "powerkey.session.new_node", FT_UINT8, BASE_HEX_DEC,
                nullptr, "The keypad moved to this node id"),
        make_hf(&hf_protocol, "Protocol now", "powerkey.session.protocol", FT_STRING, BASE_NONE,
                nullptr, "The keypad switched to this protocol (j1939 or canopen)"),
        make_hf(&hf_new_address, "J1939 address now", "powerkey.session.new_address", FT_UINT8,
                BASE_HEX_DEC, nullptr, "The keypad's J1939 address is now this one"),
        make_hf(&hf_pgn, "PGN", "powerkey.j1939.pgn", FT_UINT32, BASE_HEX, nullptr,
                "The parameter group number of a J1939 frame"),
    };
    proto_register_field_array(proto_powerkey, generic, G_N_ELEMENTS(generic));

    // One field per message field name of every model, from the library's messages.
    reg->catalog = powerkey_ws::message_fields();
    const std::size_t n = reg->catalog.size();
    reg->ids.assign(n, -1);
    reg->abbrevs.resize(n);
    reg->value_strings.resize(n);
    reg->hf.reserve(n);
    for (std::size_t i = 0; i < n; ++i) {
        const auto& spec = reg->catalog[i];
        reg->abbrevs[i] = (generic_name(spec.name) ? "powerkey.field." : "powerkey.") + spec.name;
        ftenum type = FT_UINT32;
        int display = spec.hex ? BASE_HEX : BASE_DEC;
        const void* strings = nullptr;
        switch (spec.type) {
            case powerkey_ws::field_type::boolean:
                type = FT_BOOLEAN;
                display = BASE_NONE;
                break;
            case powerkey_ws::field_type::text:
                type = FT_STRING;
                display = BASE_NONE;
                break;
            case powerkey_ws::field_type::bytes:
                type = FT_BYTES;
                display = SEP_SPACE;
                break;
            case powerkey_ws::field_type::number:
                if (!spec.value_names.empty()) {
                    auto& vs = reg->value_strings[i];
                    for (const auto& [value, name] : spec.value_names)
                        vs.push_back({value, name.c_str()});
                    vs.push_back({0, nullptr});
                    strings = vs.data();
                }
                break;
        }
        reg->hf.push_back(make_hf(&reg->ids[i], spec.name.c_str(), reg->abbrevs[i].c_str(), type,
                                  display, strings, nullptr));
    }
    proto_register_field_array(proto_powerkey, reg->hf.data(), static_cast<int>(reg->hf.size()));

    static gint* ett[] = {&ett_powerkey};
    proto_register_subtree_array(ett, G_N_ELEMENTS(ett));

    static ei_register_info ei[] = {{&ei_refused, {}}};
    ei[0].eiinfo.name = "powerkey.refused";
    ei[0].eiinfo.group = PI_MALFORMED;
    ei[0].eiinfo.severity = PI_WARN;
    ei[0].eiinfo.summary = "A frame of the keypad that does not decode";
    ei[0].eiinfo.hf_info = make_hf(nullptr, nullptr, nullptr, FT_NONE, BASE_NONE, nullptr,
                                   nullptr);  // as EXPFILL leaves it
    expert_register_field_array(expert_register_protocol(proto_powerkey), ei, G_N_ELEMENTS(ei));

    module_t* module = prefs_register_protocol(proto_powerkey, apply_preferences);
    pref_model = powerkey_ws::default_model();
    reg->model_help = "The PowerKey model on the bus, as the tool's --model takes it: " +
                      powerkey_ws::model_list() +
                      ", in any case and as the manuals write them (PKP-2400-LI) or the keypad "
                      "reports them (PKU2400)";
    prefs_register_string_preference(module, "model", "Keypad model", reg->model_help.c_str(),
                                     &pref_model_name);
    prefs_register_uint_preference(module, "node", "Node id (hex)",
                                   "The keypad's node id at the start of the capture, 1..7F "
                                   "hex; the plugin follows node-id changes from there",
                                   16, &pref_node);

    register_init_routine(init_capture);
    register_cleanup_routine(cleanup_capture);
}

// Bytes from the bus shown to the user: escaped (non-printable characters as \xNN).
const char* escaped(std::string_view s) {
    return format_text(wmem_packet_scope(), reinterpret_cast<const guchar*>(s.data()), s.size());
}

std::string session_notes(const powerkey_ws::frame_record& r) {
    std::string s;
    char b[48];
    if (r.sdo == "reply") {
        std::snprintf(b, sizeof b, "  [reply to %04Xh sub %u]", r.reply_index,
                      static_cast<unsigned>(r.reply_subindex));
        s += b;
    } else if (r.sdo == "unanswered") {
        s += "  [reply to no request]";
    }
    if (r.upload_done) s += std::string("  [text: \"") + escaped(r.upload_text()) + "\"]";
    if (!r.upload_error.empty()) s += "  [upload failed: " + std::string(r.upload_error) + "]";
    if (r.new_node != 0) {
        std::snprintf(b, sizeof b, "  [node id now %02Xh]", static_cast<unsigned>(r.new_node));
        s += b;
    }
    if (!r.new_protocol.empty()) s += "  [protocol now " + std::string(r.new_protocol) + "]";
    if (r.address_moved) {
        std::snprintf(b, sizeof b, "  [J1939 address now %02Xh]",
                      static_cast<unsigned>(r.new_address));
        s += b;
    }
    return s;
}

void add_message_field(proto_tree* tree, tvbuff_t* tvb, gint length,
                       const powerkey_ws::field_out& f) {
    const int id = reg->ids[f.spec];
    switch (reg->catalog[f.spec].type) {
        case powerkey_ws::field_type::boolean:
            proto_tree_add_boolean_format_value(tree, id, tvb, 0, length, f.flag ? 1u : 0u, "%s",
                                                f.shown.c_str());
            break;
        case powerkey_ws::field_type::text:
            proto_tree_add_string(tree, id, tvb, 0, length, f.text.c_str());
            break;
        case powerkey_ws::field_type::bytes: {
            proto_item* item = proto_tree_add_bytes_with_length(
                tree, id, tvb, 0, length, f.bytes.data(), static_cast<gint>(f.bytes.size()));
            proto_item_set_text(item, "%s: %s", reg->catalog[f.spec].name.c_str(),
                                f.shown.c_str());  // upper-case hex, as the tool writes it
            break;
        }
        case powerkey_ws::field_type::number:
            proto_tree_add_uint_format_value(tree, id, tvb, 0, length,
                                             static_cast<guint32>(f.number), "%s", f.shown.c_str());
            break;
    }
}

int dissect_powerkey(tvbuff_t* tvb, packet_info* pinfo, proto_tree* tree, void* data) {
    const auto* can = static_cast<const can_info_t*>(data);
    if (can == nullptr || can->fd || (can->id & (CAN_RTR_FLAG | CAN_ERR_FLAG)) != 0 || !reg)
        return 0;
    const bool extended = (can->id & CAN_EFF_FLAG) != 0;
    const guint length = tvb_captured_length(tvb);
    if (length > 8) return 0;
    const auto* bytes = length == 0 ? nullptr : tvb_get_ptr(tvb, 0, static_cast<gint>(length));
    const powerkey_ws::frame_in in{
        can->id & (extended ? CAN_EFF_MASK : CAN_SFF_MASK), extended, {bytes, length}};

    auto* record = static_cast<powerkey_ws::frame_record*>(
        p_get_proto_data(wmem_file_scope(), pinfo, proto_powerkey, 0));
    if (record == nullptr) {
        if (PINFO_FD_VISITED(pinfo) || !follower) return 0;
        void* memory = wmem_alloc(wmem_file_scope(), sizeof(powerkey_ws::frame_record));
        record = new (memory) powerkey_ws::frame_record(follower->step(in));
        p_add_proto_data(wmem_file_scope(), pinfo, proto_powerkey, 0, record);
    }
    if (!record->claimed) return 0;

    const auto v = powerkey_ws::view(in, *record, reg->catalog);
    const gint span = static_cast<gint>(length);

    std::string line;
    if (v.decoded) {
        line = v.summary;
    } else {
        char b[16];
        std::snprintf(b, sizeof b, "node %02Xh  ", static_cast<unsigned>(v.node));
        // A J1939 frame has no node: "j1939  error: ...", as the tool writes it.
        line = (v.function == "j1939" ? std::string() : std::string(b)) + v.function +
               "  error: " + v.error;
    }
    line += session_notes(*record);

    col_set_str(pinfo->cinfo, COL_PROTOCOL, "PowerKey");
    col_clear(pinfo->cinfo, COL_INFO);
    col_add_str(pinfo->cinfo, COL_INFO, line.c_str());

    proto_item* top = proto_tree_add_item(tree, proto_powerkey, tvb, 0, -1, ENC_NA);
    proto_item_append_text(top, ", %s", line.c_str());
    proto_tree* t = proto_item_add_subtree(top, ett_powerkey);

    if (const auto m = powerkey_ws::model_of(record->model))
        proto_tree_add_string(t, hf_model, tvb, 0, 0, std::string(powerkey::to_string(*m)).c_str());
    proto_tree_add_string(t, hf_function, tvb, 0, 0, v.function.c_str());
    proto_tree_add_uint(t, hf_node, tvb, 0, 0, v.node);
    if (v.decoded) {
        proto_tree_add_string(t, hf_kind, tvb, 0, span, v.kind.c_str());
    } else {
        proto_tree_add_string(t, hf_error, tvb, 0, span, v.error.c_str());
        expert_add_info_format(pinfo, top, &ei_refused, "PowerKey %s frame refused: %s",
                               v.function.c_str(), v.error.c_str());
    }
    if (v.sdo_index) proto_tree_add_uint(t, hf_sdo_index, tvb, 0, span, *v.sdo_index);
    if (v.sdo_subindex) proto_tree_add_uint(t, hf_sdo_subindex, tvb, 0, span, *v.sdo_subindex);
    if (v.pgn) proto_tree_add_uint(t, hf_pgn, tvb, 0, 0, *v.pgn);
    for (const auto& f : v.fields) add_message_field(t, tvb, span, f);

    if (!record->sdo.empty()) {
        const std::string pairing(record->sdo);
        proto_tree_add_string(t, hf_sdo_pairing, tvb, 0, 0, pairing.c_str());
    }
    if (record->sdo == "reply") {
        proto_tree_add_uint(t, hf_reply_index, tvb, 0, 0, record->reply_index);
        proto_tree_add_uint(t, hf_reply_subindex, tvb, 0, 0, record->reply_subindex);
    }
    if (record->upload_done)
        proto_tree_add_string(t, hf_text, tvb, 0, 0, escaped(record->upload_text()));
    if (!record->upload_error.empty())
        proto_tree_add_string(t, hf_upload_error, tvb, 0, 0,
                              std::string(record->upload_error).c_str());
    if (record->new_node != 0) proto_tree_add_uint(t, hf_new_node, tvb, 0, 0, record->new_node);
    if (!record->new_protocol.empty())
        proto_tree_add_string(t, hf_protocol, tvb, 0, 0, std::string(record->new_protocol).c_str());
    if (record->address_moved)
        proto_tree_add_uint(t, hf_new_address, tvb, 0, 0, record->new_address);
    return static_cast<int>(length);
}

gboolean dissect_powerkey_heuristic(tvbuff_t* tvb, packet_info* pinfo, proto_tree* tree,
                                    void* data) {
    const auto* can = static_cast<const can_info_t*>(data);
    if (can == nullptr || (can->id & CAN_EFF_FLAG) == 0) return FALSE;  // 11-bit: can.id
    return dissect_powerkey(tvb, pinfo, tree, data) > 0 ? TRUE : FALSE;
}

void register_handoff() {
    dissector_handle_t handle = create_dissector_handle(dissect_powerkey, proto_powerkey);
    // Every 11-bit identifier that no other dissector has claimed (Wireshark 4.0 has none).
    dissector_table_t can_id = find_dissector_table("can.id");
    for (guint32 id = 0; id <= CAN_SFF_MASK; ++id)
        if (can_id != nullptr && dissector_get_uint_handle(can_id, id) == nullptr)
            dissector_add_uint("can.id", id, handle);
    heur_dissector_add("can", dissect_powerkey_heuristic, "PowerKey keypad J1939 frames",
                       "powerkey_can", proto_powerkey, HEURISTIC_ENABLE);
    // With "Decode As" J1939 (can.subdissector), Wireshark's own J1939 dissector takes every
    // 29-bit frame before the heuristics, and hands each PGN's data on through its "j1939.pgn"
    // table (with the CAN frame's info): the plugin sits there for the keypads' PGNs (EF00h,
    // A700h, A600h, EE00h), so the J1939 tree and the keypad's show together.
    if (find_dissector_table("j1939.pgn") != nullptr)
        for (const guint32 pgn : {0xEF00u, 0xA700u, 0xA600u, 0xEE00u})
            dissector_add_uint("j1939.pgn", pgn, handle);
}

}  // namespace

extern "C" void plugin_register(void) {
    static bool registered = false;  // once, whether preloaded or found in a plugin directory
    if (registered) return;
    registered = true;
    static proto_plugin plugin;
    plugin.register_protoinfo = register_protoinfo;
    plugin.register_handoff = register_handoff;
    proto_register_plugin(&plugin);
}

namespace {
// Wireshark reads no plugin directory but the system's when it runs as root (or setuid), so
// scripts/tshark.sh then loads the plugin with LD_PRELOAD and sets POWERKEY_WIRESHARK_PRELOAD:
// the plugin registers itself at load time, before Wireshark initialises its dissectors.
[[gnu::constructor]] void register_when_preloaded() {
    if (std::getenv("POWERKEY_WIRESHARK_PRELOAD") != nullptr) plugin_register();
}
}  // namespace
