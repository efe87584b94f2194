// H.264 in an MP4 container: libavcodec encodes (libx264 where Debian's build has it, else any
// H.264 encoder the library offers), libswscale turns the drawn RGB frames into the encoder's
// YUV 4:2:0, libavformat writes the container.
//
// The MP4 muxer goes back to the start of the file at the end to write the sizes of what came
// before, so the container is written into memory, where it can seek, and handed to OutputFile
// whole at the end. A pipe or a device is then written in place like any other output, and a
// clip that fails or is cancelled never reaches the disk at all. A slide's clip is megabytes.

#include "app/clips/ClipEncoder.h"
#include "app/io/OutputFile.h"

#include <QByteArray>
#include <QImage>

extern "C" {
#include <libavcodec/avcodec.h>
#include <libavformat/avformat.h>
#include <libavutil/error.h>
#include <libavutil/imgutils.h>
#include <libavutil/log.h>
#include <libavutil/opt.h>
#include <libswscale/swscale.h>
}

#include <algorithm>
#include <cstring>

namespace phasebox {

namespace {

QString avError(int code) {
    char text[AV_ERROR_MAX_STRING_SIZE] = {};
    av_strerror(code, text, sizeof text);
    return QString::fromUtf8(text);
}

// A growing byte buffer that libavformat writes and seeks in.
struct MemoryFile {
    QByteArray bytes;
    qint64 position = 0;

    static int write(void* opaque, uint8_t* data, int size) {
        auto* self = static_cast<MemoryFile*>(opaque);
        const qint64 end = self->position + size;
        if (end > self->bytes.size()) self->bytes.resize(end);
        std::memcpy(self->bytes.data() + self->position, data, static_cast<std::size_t>(size));
        self->position = end;
        return size;
    }
    static int64_t seek(void* opaque, int64_t offset, int whence) {
        auto* self = static_cast<MemoryFile*>(opaque);
        switch (whence & ~AVSEEK_FORCE) {
            case AVSEEK_SIZE:
                return self->bytes.size();
            case SEEK_SET:
                self->position = offset;
                break;
            case SEEK_CUR:
                self->position += offset;
                break;
            case SEEK_END:
                self->position = self->bytes.size() + offset;
                break;
            default:
                return AVERROR(EINVAL);
        }
        return self->position;
    }
};

class Mp4Encoder final : public ClipEncoder {
public:
    Mp4Encoder(const ClipSpec& spec, OutputFile& out) : spec_(spec), out_(out) {}
    ~Mp4Encoder() override {
        sws_freeContext(scaler_);
        av_frame_free(&frame_);
        av_packet_free(&packet_);
        avcodec_free_context(&codec_);
        if (format_) {
            if (format_->pb) {
                av_freep(&format_->pb->buffer);
                avio_context_free(&format_->pb);
            }
            avformat_free_context(format_);
        }
    }

    bool open() {
        // The libraries' own log lines would reach standard error, which carries only
        // "phasebox-cli:" lines (CONTRACT.md §4); every failure is reported from its return code.
        av_log_set_level(AV_LOG_QUIET);
        if (avformat_alloc_output_context2(&format_, nullptr, "mp4", nullptr) < 0 || !format_)
            return fail(QStringLiteral("this FFmpeg cannot write MP4"));
        const AVCodec* codec = avcodec_find_encoder_by_name("libx264");
        if (!codec) codec = avcodec_find_encoder(AV_CODEC_ID_H264);
        if (!codec) return fail(QStringLiteral("this FFmpeg has no H.264 encoder"));
        stream_ = avformat_new_stream(format_, nullptr);
        codec_ = avcodec_alloc_context3(codec);
        frame_ = av_frame_alloc();
        packet_ = av_packet_alloc();
        if (!stream_ || !codec_ || !frame_ || !packet_)
            return fail(QStringLiteral("out of memory"));
        codec_->width = spec_.size.width();
        codec_->height = spec_.size.height();
        codec_->time_base = AVRational{1, spec_.fps};
        codec_->framerate = AVRational{spec_.fps, 1};
        codec_->pix_fmt = AV_PIX_FMT_YUV420P;
        codec_->gop_size = 2 * spec_.fps;
        // No B-frames: every frame is presented in the order it is decoded, so the MP4 needs no
        // edit list and its duration is exactly frames / fps.
        codec_->max_b_frames = 0;
        // libswscale converts with the BT.601 matrix into limited range; say so.
        codec_->colorspace = AVCOL_SPC_SMPTE170M;
        codec_->color_range = AVCOL_RANGE_MPEG;
        if (format_->oformat->flags & AVFMT_GLOBALHEADER)
            codec_->flags |= AV_CODEC_FLAG_GLOBAL_HEADER;
        if (std::strcmp(codec->name, "libx264") == 0) {
            // Flat colours and thin lines: "animation" keeps their edges; crf 20 is visually
            // lossless for drawings at a few hundred kilobytes per second.
            av_opt_set(codec_->priv_data, "preset", "medium", 0);
            av_opt_set(codec_->priv_data, "tune", "animation", 0);
            av_opt_set(codec_->priv_data, "crf", "20", 0);
        }
        if (const int e = avcodec_open2(codec_, codec, nullptr); e < 0)
            return fail(QStringLiteral("cannot start the H.264 encoder: ") + avError(e));
        if (avcodec_parameters_from_context(stream_->codecpar, codec_) < 0)
            return fail(QStringLiteral("cannot describe the H.264 stream"));
        stream_->time_base = codec_->time_base;
        stream_->avg_frame_rate = codec_->framerate;

        constexpr int kBufferSize = 1 << 16;
        auto* buffer = static_cast<unsigned char*>(av_malloc(kBufferSize));
        format_->pb = buffer ? avio_alloc_context(buffer, kBufferSize, 1, &memory_, nullptr,
                                                  &MemoryFile::write, &MemoryFile::seek)
                             : nullptr;
        if (!format_->pb) {
            av_free(buffer);
            return fail(QStringLiteral("out of memory"));
        }
        format_->flags |= AVFMT_FLAG_CUSTOM_IO;
        if (const int e = avformat_write_header(format_, nullptr); e < 0)
            return fail(QStringLiteral("cannot start the MP4 file: ") + avError(e));

        frame_->format = codec_->pix_fmt;
        frame_->width = codec_->width;
        frame_->height = codec_->height;
        if (av_frame_get_buffer(frame_, 0) < 0) return fail(QStringLiteral("out of memory"));
        scaler_ = sws_getContext(codec_->width, codec_->height, AV_PIX_FMT_RGB32, codec_->width,
                                 codec_->height, AV_PIX_FMT_YUV420P, SWS_BICUBIC, nullptr, nullptr,
                                 nullptr);
        if (!scaler_) return fail(QStringLiteral("cannot convert the frames to YUV 4:2:0"));
        return true;
    }

    bool addFrame(const QImage& image) override {
        if (image.size() != spec_.size)
            return fail(QStringLiteral("a frame of the wrong size was drawn"));
        // QImage's ARGB32 is FFmpeg's RGB32: a 32-bit 0xAARRGGBB in the machine's byte order.
        const QImage rgb = image.convertToFormat(QImage::Format_ARGB32);
        const uint8_t* planes[1] = {rgb.constBits()};
        const int strides[1] = {static_cast<int>(rgb.bytesPerLine())};
        if (av_frame_make_writable(frame_) < 0) return fail(QStringLiteral("out of memory"));
        sws_scale(scaler_, planes, strides, 0, rgb.height(), frame_->data, frame_->linesize);
        frame_->pts = next_++;
        return send(frame_);
    }

    bool finish() override {
        if (!send(nullptr)) return false;
        if (const int e = av_write_trailer(format_); e < 0)
            return fail(QStringLiteral("cannot finish the MP4 file: ") + avError(e));
        avio_flush(format_->pb);
        // Handed over in pieces: a write that blocks (a pipe) can then be interrupted between
        // them.
        constexpr qsizetype kPiece = 1 << 20;
        for (qsizetype at = 0; at < memory_.bytes.size(); at += kPiece)
            if (!out_.write(memory_.bytes.mid(at, kPiece))) return fail(out_.error());
        return true;
    }

private:
    bool fail(const QString& message) {
        if (error_.isEmpty()) error_ = message;
        return false;
    }

    // Sends a frame (nullptr: the end) and writes every packet the encoder has ready.
    bool send(AVFrame* frame) {
        if (const int e = avcodec_send_frame(codec_, frame); e < 0)
            return fail(QStringLiteral("the H.264 encoder failed: ") + avError(e));
        for (;;) {
            const int e = avcodec_receive_packet(codec_, packet_);
            if (e == AVERROR(EAGAIN) || e == AVERROR_EOF) return true;
            if (e < 0) return fail(QStringLiteral("the H.264 encoder failed: ") + avError(e));
            if (packet_->duration == 0) packet_->duration = 1;
            av_packet_rescale_ts(packet_, codec_->time_base, stream_->time_base);
            packet_->stream_index = stream_->index;
            const int w = av_interleaved_write_frame(format_, packet_);
            av_packet_unref(packet_);
            if (w < 0) return fail(QStringLiteral("cannot write the MP4 file: ") + avError(w));
        }
    }

    ClipSpec spec_;
    OutputFile& out_;
    MemoryFile memory_;
    AVFormatContext* format_ = nullptr;
    AVStream* stream_ = nullptr;
    AVCodecContext* codec_ = nullptr;
    AVFrame* frame_ = nullptr;
    AVPacket* packet_ = nullptr;
    SwsContext* scaler_ = nullptr;
    int64_t next_ = 0;
};

}  // namespace

std::unique_ptr<ClipEncoder> openMp4Encoder(const ClipSpec& spec, OutputFile& out, QString* error) {
    auto encoder = std::make_unique<Mp4Encoder>(spec, out);
    if (encoder->open()) return encoder;
    if (error) *error = out.path() + QStringLiteral(": ") + encoder->error();
    return nullptr;
}

}  // namespace phasebox
