// The tool's log reader on Vector BLF files built from the fuzzer's bytes, so that it reaches
// what raw bytes almost never do: objects inside zlib-compressed log containers, objects split
// across containers (the tail one container carries into the next), containers inside
// containers, sizes that lie, padding left out, damaged compressed data. Properties:
// fuzz/log_reader.hpp (the same file whole and in chunks; the caps of logs::limits, under
// libFuzzer's -rss_limit_mb).
//
// The recipe: one byte for the file header (the writers' 144 bytes, or a size of its own), then
// operations until the input ends, each one byte and its arguments:
//   0, 1  a CAN object (CAN_MESSAGE, CAN_MESSAGE2, CAN_FD_MESSAGE(_64), CAN_ERROR_EXT or another
//         type) added to the pending stream of objects that go into containers
//   2     the first k bytes of the stream into a container: stored, zlib, or an unknown method;
//         its unpacked size true or any; padded to 4 bytes or not
//   3     a CAN object at the top level
//   4     bytes of the input as they are (junk between objects)
//   5     a container holding a container of the first k bytes of the stream
//   6     a container stating any unpacked size over little data
//   7     an object stating any size, at the top level or in the stream
// and the rest of the stream in one last container.
#include "log_reader.hpp"

#include <zlib.h>

#include <string>

namespace {
using namespace powerkey_fuzz;

void put_le(std::string& s, std::uint64_t v, int bytes) {
    for (int i = 0; i < bytes; ++i) s += static_cast<char>((v >> (8 * i)) & 0xFF);
}

std::string take_bytes(input& in, std::size_t n) {
    std::string s;
    for (std::size_t i = 0; i < n && !in.empty(); ++i) s += static_cast<char>(in.u8());
    return s;
}

// "LOBJ", header size, header version, object size, type: the base header; `size` 0: the true
// size.
std::string object_header(std::uint16_t header_size, std::uint16_t version, std::uint32_t size,
                          std::uint32_t type) {
    std::string s = "LOBJ";
    put_le(s, header_size, 2);
    put_le(s, version, 2);
    put_le(s, size, 4);
    put_le(s, type, 4);
    return s;
}

// A CAN object: header version 1 (32 bytes: flags, client, version, time stamp), then its body.
std::string can_object(input& in) {
    constexpr std::uint32_t types[] = {1, 86, 100, 101, 73, 65};
    const std::uint8_t choice = in.u8();
    const std::uint32_t type = types[choice % 6];
    const std::size_t body = type == 100 ? 84 : type == 101 ? 104 : type == 65 ? in.u8() % 64 : 16;
    const std::uint16_t version = (choice & 0x40) != 0 ? in.u8() : 1;
    std::string fields;
    put_le(fields, in.u8() & 1, 4);                  // flags: 1 ten microseconds, else nanoseconds
    put_le(fields, 0, 4);                            // client index, object version
    put_le(fields, in.integer<std::uint32_t>(), 8);  // time stamp
    std::string b = take_bytes(in, body);
    b.resize(body, '\0');
    const auto size = static_cast<std::uint32_t>(32 + body);
    return object_header(32, version, (choice & 0x80) != 0 ? in.integer<std::uint32_t>() : size,
                         type) +
           fields + b;
}

// A log container (type 10) of `data`: method 0 stored, 2 zlib, or another; `unpacked` its
// stated unpacked size.
std::string container(std::string_view data, std::uint16_t method, std::uint32_t unpacked) {
    std::string payload;
    if (method == 2) {
        uLongf n = compressBound(static_cast<uLong>(data.size()));
        payload.resize(n);
        if (compress2(reinterpret_cast<Bytef*>(payload.data()), &n,
                      reinterpret_cast<const Bytef*>(data.data()), static_cast<uLong>(data.size()),
                      Z_BEST_SPEED) != Z_OK)
            n = 0;
        payload.resize(n);
    } else {
        payload = data;
    }
    std::string s = object_header(16, 1, static_cast<std::uint32_t>(32 + payload.size()), 10);
    put_le(s, method, 2);
    put_le(s, 0, 6);
    put_le(s, unpacked, 4);
    put_le(s, 0, 4);
    return s + payload;
}

void pad(std::string& file, bool padded) {
    // Top-level objects are followed by size % 4 padding bytes (log_formats.cpp).
    if (padded && file.size() % 4 != 0) file.append(4 - file.size() % 4, '\0');
}

std::string build(input& in) {
    std::string file = "LOGG";
    const std::uint8_t head = in.u8();
    const std::uint32_t header_size = (head & 1) == 0 ? 144 : in.integer<std::uint16_t>();
    put_le(file, header_size, 4);
    std::string header(header_size > 8 && header_size < 8192 ? header_size - 8 : 0, '\0');
    if (header.size() >= 48) {  // the start time, a SYSTEMTIME at byte 40: 2023-11-14 22:13:20
        const std::uint16_t st[] = {2023, 11, 2, 14, 22, 13, 20, 0};
        for (std::size_t i = 0; i < 8; ++i) {
            header[32 + 2 * i] = static_cast<char>(st[i] & 0xFF);
            header[33 + 2 * i] = static_cast<char>(st[i] >> 8);
        }
    }
    file += header;
    std::string stream;  // objects waiting for a container
    while (!in.empty() && file.size() < (1u << 20)) {
        const std::uint8_t op = in.u8();
        switch (op % 8) {
            case 0:
            case 1: stream += can_object(in); break;
            case 2:
            case 5: {
                const std::size_t k = in.integer<std::uint16_t>() % (stream.size() + 1);
                std::string data = stream.substr(0, k);
                stream.erase(0, k);
                const std::uint8_t m = (op >> 3) & 3;
                const std::uint16_t method = m == 3 ? in.u8() : m == 0 ? 0 : 2;
                if (op % 8 == 5) data = container(data, method, static_cast<std::uint32_t>(k));
                const auto unpacked = (op & 0x80) != 0 ? in.integer<std::uint32_t>()
                                                       : static_cast<std::uint32_t>(data.size());
                file += container(data, method, unpacked);
                pad(file, (op & 0x40) == 0);
                break;
            }
            case 3:
                file += can_object(in);
                pad(file, (op & 0x40) == 0);
                break;
            case 4: file += take_bytes(in, in.u8() % 32); break;
            case 6: {
                const auto data = take_bytes(in, in.u8() % 64);
                file += container(data, (op & 0x10) != 0 ? 0 : 2, in.integer<std::uint32_t>());
                pad(file, true);
                break;
            }
            case 7: {
                // (One read after the other: the operands of + are read in no set order.)
                const auto size = in.integer<std::uint32_t>();
                const auto o = object_header(32, 1, size, 1) + take_bytes(in, in.u8() % 48);
                ((op & 0x10) != 0 ? stream : file) += o;
                break;
            }
        }
    }
    if (!stream.empty()) file += container(stream, 2, static_cast<std::uint32_t>(stream.size()));
    return file;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    input in(data, size);
    const std::string file = build(in);
    check_reader(file, false);
    return 0;
}
