#include "io/image_io.h"

#include <ImfChannelList.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfIO.h>
#include <ImfInputFile.h>
#include <ImfOutputFile.h>
#include <cstring>
#include <stdexcept>
#include <string>

#include "core/atomic_file.h"

#define STB_IMAGE_WRITE_IMPLEMENTATION
#define STBIW_WINDOWS_UTF8
#include <stb_image_write.h>
#define STB_IMAGE_IMPLEMENTATION
#define STB_IMAGE_STATIC
#define STBI_ONLY_PNG
#include <stb_image.h>

namespace engine::io {

namespace fs = std::filesystem;

namespace {

// OpenEXR's output stream over an AtomicFile: OpenEXR writes the line-offset table last, by
// seeking back, so the file needs tell and seek; a failed write throws, which OpenEXR passes on.
class AtomicExrStream final : public Imf::OStream {
public:
    explicit AtomicExrStream(AtomicFile& file) : Imf::OStream(file.target().c_str()), mFile(file) {}
    void write(const char c[], int n) override { check(mFile.write(c, std::size_t(n))); }
    std::uint64_t tellp() override { return mFile.tell(); }
    void seekp(std::uint64_t pos) override { check(mFile.seek(pos)); }

private:
    static void check(const Status& s) {
        if (!s) throw std::runtime_error(s.error().message);
    }
    AtomicFile& mFile;
};

}  // namespace

Status writePng(const fs::path& path, std::uint32_t width, std::uint32_t height,
                std::span<const std::uint32_t> rgba8) {
    if (rgba8.size() != std::size_t(width) * height)
        return makeError("{}: image size mismatch", path.string());
    // stb encodes into memory (its own file writer ignores fwrite and fclose errors); the
    // checked writer puts the bytes on disk.
    std::string png;
    auto append = [](void* context, void* data, int size) {
        static_cast<std::string*>(context)->append(static_cast<const char*>(data),
                                                   std::size_t(size));
    };
    if (!stbi_write_png_to_func(append, &png, int(width), int(height), 4, rgba8.data(),
                                int(width * 4)))
        return makeError("{}: cannot encode PNG", path.string());
    return writeFileAtomically(path, png);
}

Result<PngImage> readPng(const fs::path& path) {
    int w = 0, h = 0, channels = 0;
    stbi_uc* data = stbi_load(path.c_str(), &w, &h, &channels, 4);
    if (!data) return makeError("{}: cannot read PNG: {}", path.string(), stbi_failure_reason());
    PngImage img;
    img.width = std::uint32_t(w);
    img.height = std::uint32_t(h);
    img.rgba8.resize(std::size_t(w) * h);
    std::memcpy(img.rgba8.data(), data, img.rgba8.size() * 4u);
    stbi_image_free(data);
    return img;
}

Status writeExr(const fs::path& path, std::uint32_t width, std::uint32_t height,
                std::span<const glm::vec4> linear) {
    if (linear.size() != std::size_t(width) * height)
        return makeError("{}: image size mismatch", path.string());
    return writeFileAtomically(path, [&](AtomicFile& atomic) -> Status {
        try {
            Imf::Header header{int(width), int(height)};
            const char* names[] = {"R", "G", "B", "A"};
            for (const char* n : names) header.channels().insert(n, Imf::Channel(Imf::FLOAT));
            AtomicExrStream stream(atomic);
            Imf::OutputFile file(stream, header);
            Imf::FrameBuffer fb;
            char* base = const_cast<char*>(reinterpret_cast<const char*>(linear.data()));
            for (int c = 0; c < 4; ++c) {
                fb.insert(names[c], Imf::Slice(Imf::FLOAT, base + c * sizeof(float),
                                               sizeof(glm::vec4), sizeof(glm::vec4) * width));
            }
            file.setFrameBuffer(fb);
            file.writePixels(int(height));
        } catch (const std::exception& e) {
            // A failed write already names the path and the reason; anything else is OpenEXR's.
            if (Status s = atomic.status(); !s) return s;
            return makeError("{}: cannot write EXR: {}", path.string(), e.what());
        }
        return {};
    });
}

Result<ExrImage> readExr(const fs::path& path) {
    try {
        Imf::InputFile file(path.c_str());
        Imath::Box2i dw = file.header().dataWindow();
        ExrImage img;
        img.width = std::uint32_t(dw.max.x - dw.min.x + 1);
        img.height = std::uint32_t(dw.max.y - dw.min.y + 1);
        img.pixels.assign(std::size_t(img.width) * img.height, glm::vec4(0.0f, 0.0f, 0.0f, 1.0f));
        Imf::FrameBuffer fb;
        char* base =
            reinterpret_cast<char*>(img.pixels.data()) -
            (std::ptrdiff_t(dw.min.x) + std::ptrdiff_t(dw.min.y) * img.width) * sizeof(glm::vec4);
        const char* names[] = {"R", "G", "B", "A"};
        for (int c = 0; c < 4; ++c) {
            fb.insert(names[c],
                      Imf::Slice(Imf::FLOAT, base + c * sizeof(float), sizeof(glm::vec4),
                                 sizeof(glm::vec4) * img.width, 1, 1, c == 3 ? 1.0 : 0.0));
        }
        file.setFrameBuffer(fb);
        file.readPixels(dw.min.y, dw.max.y);
        return img;
    } catch (const std::exception& e) {
        return makeError("{}: cannot read EXR: {}", path.string(), e.what());
    }
}

}  // namespace engine::io
