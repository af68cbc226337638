// One SDO parser: every public entry point that reads an SDO frame agrees with the SDO engine
// (canopen::sdo_request_op / sdo_response_op) on the same frame: the CiA 301 decoders
// (canopen::decode_sdo_request / decode_sdo_response) and the keypad codec (decode(frame, node,
// model)) for every model, and the session (which takes what decode returned). Shared by the
// sweep of tests/test_powerkey.cpp (every manual row and thousands of frames around them) and
// the `decode` fuzz target (every corpus entry).
#ifndef POWERKEY_TESTS_SDO_AGREEMENT_HPP
#define POWERKEY_TESTS_SDO_AGREEMENT_HPP

#include <powerkey/canopen/sdo.hpp>
#include <powerkey/keypad/codec.hpp>
#include <powerkey/names.hpp>
#include <powerkey/session.hpp>

#include <string_view>
#include <variant>

namespace sdo_agreement {

using namespace powerkey;
using canopen::sdo_op;

// The errors only a keypad's dictionary can give (the engine passed the frame).
constexpr bool dictionary_error(errc e) noexcept {
    return e == errc::unknown_object || e == errc::unknown_command || e == errc::size_mismatch ||
           e == errc::reserved_not_zero || e == errc::value_out_of_range;
}

// Whether a keypad message is the frame `op` at `address` says (the message's own object or
// address, looked up in the model's dictionary).
constexpr bool matches(const message& m, sdo_op op, canopen::sdo_address address,
                       model md) noexcept {
    const auto at = [md, address](object o) {
        const auto row = find_row(info(md)->dictionary, o);
        return row && row->address == address;
    };
    switch (op) {
        case sdo_op::expedited_download:
            if (const auto* w = std::get_if<sdo_write>(&m)) return at(w->object);
            return std::holds_alternative<command>(m) && at(object::command_module);
        case sdo_op::upload: {
            const auto* r = std::get_if<sdo_read>(&m);
            return r != nullptr && at(r->object);
        }
        case sdo_op::segment_request:
            return std::holds_alternative<canopen::sdo_segment_request>(m);
        case sdo_op::abort_request: {
            const auto* a = std::get_if<canopen::sdo_abort_request>(&m);
            return a != nullptr && a->abort.address == address;
        }
        case sdo_op::download_response: {
            const auto* r = std::get_if<sdo_write_reply>(&m);
            return r != nullptr && at(r->object);
        }
        case sdo_op::expedited_upload: {
            const auto* r = std::get_if<sdo_read_reply>(&m);
            return r != nullptr && at(r->object);
        }
        case sdo_op::upload_initiate: {
            const auto* i = std::get_if<canopen::sdo_upload_initiate_response>(&m);
            return i != nullptr && i->address == address;
        }
        case sdo_op::segment: return std::holds_alternative<canopen::sdo_segment_response>(m);
        case sdo_op::abort_response: {
            const auto* a = std::get_if<canopen::sdo_abort_response>(&m);
            return a != nullptr && a->abort.address == address;
        }
    }
    return false;
}

// The CiA 301 alternative of each engine op.
constexpr bool matches(const canopen::sdo_request& r, sdo_op op) noexcept {
    switch (op) {
        case sdo_op::expedited_download:
            return std::holds_alternative<canopen::sdo_download_request>(r);
        case sdo_op::upload: return std::holds_alternative<canopen::sdo_upload_request>(r);
        case sdo_op::segment_request:
            return std::holds_alternative<canopen::sdo_segment_request>(r);
        case sdo_op::abort_request: return std::holds_alternative<canopen::sdo_abort>(r);
        default: return false;
    }
}
constexpr bool matches(const canopen::sdo_response& r, sdo_op op) noexcept {
    switch (op) {
        case sdo_op::download_response:
            return std::holds_alternative<canopen::sdo_download_response>(r);
        case sdo_op::expedited_upload:
            return std::holds_alternative<canopen::sdo_upload_response>(r);
        case sdo_op::upload_initiate:
            return std::holds_alternative<canopen::sdo_upload_initiate_response>(r);
        case sdo_op::segment: return std::holds_alternative<canopen::sdo_segment_response>(r);
        case sdo_op::abort_response: return std::holds_alternative<canopen::sdo_abort>(r);
        default: return false;
    }
}

// "" when every entry point agrees on f for a keypad at `node`; else what differs. Frames that
// are not 8-byte SDO frames of `node` are not SDO frames here (the checks of the identifier and
// the length come before the engine and are the decoders' own).
constexpr std::string_view disagreement(const can::frame& f, canopen::node_id node) noexcept {
    if (f.is_extended() || f.size() != 8) return {};
    const bool request = f.raw_id() == canopen::cob_id(canopen::function::sdo_rx, node).value();
    const bool response = f.raw_id() == canopen::cob_id(canopen::function::sdo_tx, node).value();
    if (!request && !response) return {};
    const auto w = canopen::sdo_word::of(f);
    const auto op = request ? canopen::sdo_request_op(w) : canopen::sdo_response_op(w);
    if (request) {
        const auto cia = canopen::decode_sdo_request(f, node);
        if (op.has_value() != cia.has_value()) return "engine and decode_sdo_request disagree";
        if (!op && op.error() != cia.error()) return "decode_sdo_request refuses differently";
        if (op && !matches(*cia, *op)) return "decode_sdo_request reads another frame";
    } else {
        const auto cia = canopen::decode_sdo_response(f, node);
        if (op.has_value() != cia.has_value()) return "engine and decode_sdo_response disagree";
        if (!op && op.error() != cia.error()) return "decode_sdo_response refuses differently";
        if (op && !matches(*cia, *op)) return "decode_sdo_response reads another frame";
    }
    for (const model md : enum_values<model>()) {
        const auto k = decode(f, node, md);
        if (!op) {
            if (k.has_value() || k.error() != op.error())
                return "decode refuses otherwise than the engine";
            continue;
        }
        if (!k) {
            if (!dictionary_error(k.error())) return "decode refuses with a wire error";
            // Segments and aborts have no object to refuse.
            if (*op == sdo_op::segment_request || *op == sdo_op::abort_request ||
                *op == sdo_op::segment || *op == sdo_op::abort_response)
                return "decode refuses a segment or an abort";
            continue;
        }
        if (!matches(*k, *op, w.address(), md)) return "decode reads another frame";
        // The session takes decode's answer: an SDO frame of the keypad pairs as one.
        session<> s(md, node);
        const auto e = s.step(f);
        if (e.sdo == sdo_pairing::none) return "the session does not see the SDO frame";
        if (request && e.sdo != sdo_pairing::request) return "the session misreads a request";
    }
    return {};
}

}  // namespace sdo_agreement

#endif  // POWERKEY_TESTS_SDO_AGREEMENT_HPP
