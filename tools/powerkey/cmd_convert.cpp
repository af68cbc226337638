// powerkey convert [--to candump|pcap] [-o FILE] [FILE...]
//
// Writes any log the tool reads (input.hpp) as a candump log or as a pcap capture of SocketCAN
// frames (LINKTYPE_CAN_SOCKETCAN, 227), the form Wireshark and tshark read: data frames, remote
// frames and CAN FD frames, each with its time and interface. Error frames are counted, not
// written (most logs keep no more than that there was one).
//
// With -o FILE the output goes to a temporary file beside FILE, renamed to FILE only when every
// input was read without a problem: a failed conversion leaves no partial FILE behind.
#include "cli.hpp"
#include "commands.hpp"
#include "input.hpp"

#include <powerkey/can/candump.hpp>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cinttypes>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <string>
#include <string_view>
#include <vector>

namespace tool {
namespace {

struct convert_options {
    std::string to;      // candump or pcap; default from the -o name, else candump
    std::string output;  // -o FILE
    std::vector<std::string> files;
};

constexpr std::uint32_t linktype_can_socketcan = 227;
constexpr std::uint32_t can_eff_flag = 0x8000'0000;  // linux/can.h
constexpr std::uint32_t can_rtr_flag = 0x4000'0000;
constexpr std::uint8_t canfd_brs = 0x01;  // linux/can.h: bit-rate switch
constexpr std::uint8_t canfd_fdf = 0x04;  // linux/can.h: the frame is CAN FD

void put_le32(std::string& b, std::uint32_t v) {
    for (int i = 0; i < 4; ++i) b += static_cast<char>((v >> (8 * i)) & 0xFF);
}
void put_le16(std::string& b, std::uint16_t v) {
    b += static_cast<char>(v & 0xFF);
    b += static_cast<char>(v >> 8);
}

class converter final : public frame_handler {
public:
    converter(bool pcap, output& out) : pcap_(pcap), out_(out) {
        if (!pcap_) return;
        // pcap file header: magic, version 2.4, time zone 0, accuracy 0, snapshot length, link
        auto& b = out_.buffer();
        put_le32(b, 0xA1B2'C3D4);
        put_le16(b, 2);
        put_le16(b, 4);
        put_le32(b, 0);
        put_le32(b, 0);
        put_le32(b, 65535);
        put_le32(b, linktype_can_socketcan);
    }

    void frame(const logs::record& r) override {
        const auto d = r.frame.data();
        write(r.time, r.interface, r.frame.raw_id(), r.frame.is_extended(), false, false, false,
              static_cast<std::uint8_t>(d.size()), {d.data(), d.size()});
    }
    bool other(const logs::other_record& r) override {
        write(r.time, r.interface, r.id, r.extended, r.kind == logs::skip::remote,
              r.kind == logs::skip::fd, r.bit_rate_switch, r.length, r.data);
        return true;
    }
    [[nodiscard]] std::string_view skipped_note() const override {
        return "not converted (powerkey writes data, remote and CAN FD frames)";
    }

private:
    void write(std::string_view time, std::string_view interface, std::uint32_t id, bool extended,
               bool remote, bool fd, bool brs, std::uint8_t length,
               std::span<const std::uint8_t> data) {
        // A frame without a time keeps the time of the frame before it (0 at the start).
        if (!time.empty())
            if (const auto us = parse_seconds(time)) us_ = *us;
        auto& b = out_.buffer();
        if (pcap_) {
            const std::size_t size = fd ? 72 : 16;  // struct canfd_frame, struct can_frame
            put_le32(b, static_cast<std::uint32_t>(us_ / 1'000'000));
            put_le32(b, static_cast<std::uint32_t>(us_ % 1'000'000));
            put_le32(b, static_cast<std::uint32_t>(size));
            put_le32(b, static_cast<std::uint32_t>(size));
            const std::uint32_t can_id =
                id | (extended ? can_eff_flag : 0) | (remote ? can_rtr_flag : 0);
            for (int i = 3; i >= 0; --i) b += static_cast<char>((can_id >> (8 * i)) & 0xFF);
            b += static_cast<char>(length);
            b += static_cast<char>(fd ? (canfd_fdf | (brs ? canfd_brs : 0)) : 0);
            b.append(2, '\0');
            for (std::size_t i = 0; i < size - 8; ++i)
                b += static_cast<char>(i < data.size() ? data[i] : 0);
        } else {
            char head[48];
            const int n = std::snprintf(head, sizeof head, "(%" PRId64 ".%06" PRId64 ") ",
                                        us_ / 1'000'000, us_ % 1'000'000);
            b.append(head, static_cast<std::size_t>(n));
            // An interface name is written as the log gave it when it is a plain word.
            b +=
                !interface.empty() && interface.size() <= 16 && plain(interface) ? interface : "can0";
            b += ' ';
            append_hex(b, id, extended ? 8 : 3);
            b += '#';
            if (remote) {
                b += 'R';
                if (length > 0) append_hex(b, length, 1);  // the length asked for (can-utils)
            } else {
                if (fd) {
                    b += '#';
                    append_hex(b, brs ? canfd_brs : 0, 1);
                }
                append_hex_bytes(b, data.data(), data.size());
            }
            b += '\n';
        }
        out_.maybe_flush();
    }

    bool pcap_;
    output& out_;
    std::int64_t us_ = 0;
};

int run_convert(const convert_options& o) {
    std::string to = o.to;
    if (to.empty()) to = o.output.ends_with(".pcap") ? "pcap" : "candump";
    if (to != "pcap" && to != "candump")
        return usage_error("--to: expected candump or pcap, got '" + escape(to, 32) + "'");
    const bool pcap = to == "pcap";
    if (pcap && o.output.empty() && isatty(1) != 0)
        return usage_error(
            "convert --to pcap writes a binary capture: give -o FILE.pcap or "
            "redirect standard output");
    // -o FILE: a temporary file beside it, renamed when everything was read.
    std::string temporary;
    int fd = -1;
    if (!o.output.empty()) {
        temporary = o.output + ".XXXXXX";
        fd = ::mkstemp(temporary.data());
        if (fd < 0) {
            report(file_label(o.output), std::strerror(errno));
            return status_input;
        }
        ::fchmod(fd, 0644);
        if (::dup2(fd, 1) < 0) {
            report(file_label(o.output), std::strerror(errno));
            ::close(fd);
            ::unlink(temporary.c_str());
            return status_input;
        }
        ::close(fd);
    }
    {
        output out;
        input_counts counts;
        converter c(pcap, out);
        read_inputs(o.files, c, out, counts);
        out.flush();
    }
    if (temporary.empty()) return status();
    const bool written = std::ferror(stdout) == 0 && std::fflush(stdout) == 0 && ::fsync(1) == 0;
    if (!written) report(file_label(o.output), std::strerror(errno));
    if (status() != status_ok || !written) {
        ::unlink(temporary.c_str());
        report(file_label(o.output), "not written (the input had problems, above)", false);
        return status_input;
    }
    if (::rename(temporary.c_str(), o.output.c_str()) != 0) {
        report(file_label(o.output), std::strerror(errno));
        ::unlink(temporary.c_str());
        return status_input;
    }
    return status_ok;
}

}  // namespace

void add_convert(registry& r) {
    static convert_options o;
    auto& sub = r.add({"convert", "[--to candump|pcap] [-o FILE] [FILE...]",
                       "any log as a candump log or a SocketCAN pcap capture (for Wireshark)",
                       "  --to F       candump (default) or pcap; -o NAME.pcap alone says pcap\n"
                       "  -o FILE      write FILE (only when every input was read; else nothing)\n",
                       model_use::none},
                      [] { return run_convert(o); });
    sub.add_option("--to", o.to);
    sub.add_option("-o,--output", o.output);
    sub.add_option("FILE", o.files);
}

}  // namespace tool
