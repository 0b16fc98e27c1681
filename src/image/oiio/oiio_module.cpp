// The OpenImageIO side of image/image_library.h, built as the module libglint_oiio.so and
// loaded only when a scene reads an image or writes a format other than PNG. It sees only
// OpenImageIO and the interface: no glint library is linked in, so the process keeps one copy
// of glint's state.
#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>
#include <OpenImageIO/imageio.h>

#include <memory>
#include <string>
#include <vector>

#include "image/image_library.h"

namespace glint {
namespace {

PixelType pixel_type(const OIIO::TypeDesc& t) {
    switch (t.basetype) {
        case OIIO::TypeDesc::UINT8: return PixelType::UInt8;
        case OIIO::TypeDesc::UINT16: return PixelType::UInt16;
        case OIIO::TypeDesc::HALF: return PixelType::Half;
        case OIIO::TypeDesc::FLOAT: return PixelType::Float;
        case OIIO::TypeDesc::DOUBLE: return PixelType::Double;
        default: return PixelType::Other;
    }
}

OIIO::TypeDesc type_desc(PixelType t) {
    switch (t) {
        case PixelType::UInt8: return OIIO::TypeDesc::UINT8;
        case PixelType::UInt16: return OIIO::TypeDesc::UINT16;
        case PixelType::Half: return OIIO::TypeDesc::HALF;
        case PixelType::Double: return OIIO::TypeDesc::DOUBLE;
        case PixelType::Float:
        default: return OIIO::TypeDesc::FLOAT;
    }
}

class OiioReader final : public ImageReader {
public:
    explicit OiioReader(std::unique_ptr<OIIO::ImageInput> in) : in_(std::move(in)) {
        const OIIO::ImageSpec& spec = in_->spec();
        header_.width = spec.width;
        header_.height = spec.height;
        header_.channels = spec.nchannels;
        header_.type = pixel_type(spec.format);
        header_.alpha_channel = spec.alpha_channel;
        header_.format = in_->format_name();
        header_.colorspace = spec.get_string_attribute("oiio:ColorSpace");
        header_.gamma = spec.get_float_attribute("oiio:Gamma", 0.0f);
        for (const OIIO::ParamValue& p : spec.extra_attribs)
            if (p.type() == OIIO::TypeDesc::STRING)
                header_.text.emplace_back(p.name().string(), p.get_string());
    }
    ~OiioReader() override { in_->close(); }
    const ImageHeader& header() const override { return header_; }
    std::string read(int channels, float* out) override {
        if (in_->read_image(0, 0, 0, channels, OIIO::TypeDesc::FLOAT, out)) return {};
        std::string why = in_->geterror();
        return why.empty() ? "read failed" : why;
    }

private:
    std::unique_ptr<OIIO::ImageInput> in_;
    ImageHeader header_;
};

class OiioLibrary final : public ImageLibrary {
public:
    std::unique_ptr<ImageReader> open(const std::string& path,
                                      const std::vector<std::pair<std::string, int>>& config,
                                      std::string* error) const override {
        OIIO::ImageSpec hints;
        for (const auto& [name, value] : config) hints.attribute(name, value);
        std::unique_ptr<OIIO::ImageInput> in = OIIO::ImageInput::open(path, &hints);
        if (!in) {
            *error = OIIO::geterror();
            if (error->empty()) *error = "cannot open the file";
            return nullptr;
        }
        return std::make_unique<OiioReader>(std::move(in));
    }

    std::string write(const ImageWrite& w, std::vector<unsigned char>* bytes) const override {
        OIIO::ImageSpec spec(w.width, w.height, w.channels, type_desc(w.type));
        spec.alpha_channel = w.alpha_channel;
        if (!w.channel_names.empty()) spec.channelnames = w.channel_names;
        for (const auto& [name, value] : w.attributes) {
            if (const auto* s = std::get_if<std::string>(&value))
                spec.attribute(name, *s);
            else if (const auto* i = std::get_if<int>(&value))
                spec.attribute(name, *i);
            else
                spec.attribute(name, std::get<float>(value));
        }
        OIIO::Filesystem::IOVecOutput memory(*bytes);
        std::unique_ptr<OIIO::ImageOutput> out = OIIO::ImageOutput::create(w.format);
        if (!out) return "OpenImageIO has no " + w.format + " writer";
        if (w.to_memory && (!out->supports("ioproxy") || !out->set_ioproxy(&memory)))
            return "OpenImageIO's " + w.format + " writer cannot write to memory";
        if (!out->open(w.path, spec)) {
            std::string why = out->geterror();
            return why.empty() ? "cannot create the file" : why;
        }
        bool ok = out->write_image(type_desc(w.type), w.data);
        std::string why = ok ? std::string() : out->geterror();
        if (!out->close() && ok) {
            ok = false;
            why = out->geterror();
        }
        if (!ok) return why.empty() ? "write failed" : why;
        return {};
    }

    std::string draw(int w, int h, const std::vector<DrawOp>& ops,
                     std::vector<float>* rgb) const override {
        namespace IBA = OIIO::ImageBufAlgo;
        OIIO::ImageBuf buf(OIIO::ImageSpec(w, h, 3, OIIO::TypeDesc::FLOAT));
        const float white[3] = {1, 1, 1};
        IBA::fill(buf, white);
        std::string text_error;
        for (const DrawOp& op : ops) {
            const OIIO::cspan<float> c(op.color, 3);
            switch (op.kind) {
                case DrawOp::Kind::Line: IBA::render_line(buf, op.x0, op.y0, op.x1, op.y1, c); break;
                case DrawOp::Kind::Box:
                case DrawOp::Kind::FilledBox:
                    IBA::render_box(buf, op.x0, op.y0, op.x1, op.y1, c,
                                    op.kind == DrawOp::Kind::FilledBox);
                    break;
                case DrawOp::Kind::Text: {
                    if (!text_error.empty()) break;
                    const auto ax = op.align_x < 0   ? IBA::TextAlignX::Left
                                     : op.align_x > 0 ? IBA::TextAlignX::Right
                                                      : IBA::TextAlignX::Center;
                    const auto ay = op.align_y == -2 ? IBA::TextAlignY::Baseline
                                     : op.align_y < 0 ? IBA::TextAlignY::Top
                                     : op.align_y > 0 ? IBA::TextAlignY::Bottom
                                                      : IBA::TextAlignY::Center;
                    if (!IBA::render_text(buf, op.x0, op.y0, op.text, op.font_size, op.font, c,
                                          ax, ay)) {
                        text_error = buf.geterror();
                        if (text_error.empty()) text_error = "OpenImageIO could not draw text";
                    }
                    break;
                }
            }
        }
        rgb->assign(static_cast<size_t>(w) * h * 3, 0.0f);
        buf.get_pixels(OIIO::ROI::All(), OIIO::TypeDesc::FLOAT, rgb->data());
        return text_error;
    }
};

}  // namespace
}  // namespace glint

// The module's one entry point, found with dlsym by image/image_library.cpp.
extern "C" __attribute__((visibility("default"))) const glint::ImageLibrary*
glint_image_library_v1() {
    static const glint::OiioLibrary library;
    return &library;
}
