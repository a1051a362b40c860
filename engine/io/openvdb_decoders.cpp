// Safe replacements for two decoders of OpenVDB 10.0 (Debian 12's libopenvdb10.0).
//
// Why: in that release io::bloscFromStream() and io::unzipFromStream() read a chunk marked as
// "stored uncompressed" into the caller's node buffer using the size written in the file, and
// only then compare that size with the buffer's. A damaged or hostile file therefore overflows
// the heap (our fuzz target found it within seconds). Later OpenVDB releases check first. The
// library calls both functions through its PLT, so these definitions, linked into our programs,
// replace the library's at load time; they are correct for any release with the same signature.
//
// Also checked here: a blosc chunk's header must agree with the sizes around it before blosc
// reads it (blosc trusts the header), and any stream failure is an exception.
#include <blosc.h>
#include <istream>
#include <memory>
#include <openvdb/Exceptions.h>
#include <openvdb/io/Compression.h>
#include <string>
#include <zlib.h>

namespace engine::io {
// Called by VdbReader so the linker keeps this object (and with it the replacements below).
void linkOpenVdbDecoders() {}
}  // namespace engine::io

namespace openvdb {
OPENVDB_USE_VERSION_NAMESPACE
namespace OPENVDB_VERSION_NAME {
namespace io {

namespace {

// Reads the chunk header; returns the stored size (negative: uncompressed, that many bytes).
Int64 readChunkSize(std::istream& is, const char* codec) {
    Int64 size = 0;
    is.read(reinterpret_cast<char*>(&size), sizeof(size));
    if (!is.good())
        OPENVDB_THROW(RuntimeError,
                      std::string("stream ended in the size of a ") + codec + " chunk");
    return size;
}

// An uncompressed chunk must be exactly the buffer's size: check, then read or skip.
void readStoredChunk(std::istream& is, char* data, size_t numBytes, Int64 stored,
                     const char* codec) {
    if (stored == std::numeric_limits<Int64>::min() || size_t(-stored) != numBytes)
        OPENVDB_THROW(RuntimeError,
                      std::string("a stored ") + codec + " chunk has the wrong size for its node");
    if (data == nullptr)
        is.seekg(-stored, std::ios_base::cur);
    else
        is.read(data, -stored);
    if (!is.good())
        OPENVDB_THROW(RuntimeError, std::string("stream ended inside a ") + codec + " chunk");
}

std::unique_ptr<char[]> readCompressedChunk(std::istream& is, Int64 bytes, const char* codec) {
    std::unique_ptr<char[]> buffer(new char[size_t(bytes)]);
    is.read(buffer.get(), bytes);
    if (!is.good())
        OPENVDB_THROW(RuntimeError, std::string("stream ended inside a ") + codec + " chunk");
    return buffer;
}

}  // namespace

void bloscFromStream(std::istream& is, char* data, size_t numBytes) {
    const Int64 compressed = readChunkSize(is, "blosc");
    if (compressed <= 0) return readStoredChunk(is, data, numBytes, compressed, "blosc");
    if (data == nullptr) {
        is.seekg(compressed, std::ios_base::cur);
        return;
    }
    std::unique_ptr<char[]> chunk = readCompressedChunk(is, compressed, "blosc");
    size_t expanded = 0;
    if (blosc_cbuffer_validate(chunk.get(), size_t(compressed), &expanded) != 0 ||
        expanded != numBytes)
        OPENVDB_THROW(RuntimeError, "a blosc chunk's header does not match its node");
    const int got = blosc_decompress_ctx(chunk.get(), data, numBytes, /*numinternalthreads=*/1);
    if (got < 0 || size_t(got) != numBytes)
        OPENVDB_THROW(RuntimeError, "a blosc chunk does not decompress");
}

void unzipFromStream(std::istream& is, char* data, size_t numBytes) {
    const Int64 compressed = readChunkSize(is, "zip");
    if (compressed <= 0) return readStoredChunk(is, data, numBytes, compressed, "zip");
    if (data == nullptr) {
        is.seekg(compressed, std::ios_base::cur);
        return;
    }
    std::unique_ptr<char[]> chunk = readCompressedChunk(is, compressed, "zip");
    uLongf expanded = uLongf(numBytes);
    const int status = uncompress(reinterpret_cast<Bytef*>(data), &expanded,
                                  reinterpret_cast<const Bytef*>(chunk.get()), uLong(compressed));
    if (status != Z_OK || expanded != numBytes)
        OPENVDB_THROW(RuntimeError, "a zip chunk does not decompress");
}

}  // namespace io
}  // namespace OPENVDB_VERSION_NAME
}  // namespace openvdb
