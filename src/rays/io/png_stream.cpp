#include "rays/io/png_stream.h"

#include "rays/error.h"

namespace rays {

PngStream::PngStream(int width, int height) : bytes_(width, height, 3), rowReady_(size_t(height), 0) {}

void PngStream::rowsDone(const ImageF& img, int y0, int y1) {
    for (int y = y0; y < y1; ++y) {
        const Vec3* in = &img.pixels[size_t(y) * size_t(img.width)];
        uint8_t* out = bytes_.row(y);
        for (int x = 0; x < img.width; ++x) {
            out[3 * x + 0] = toByte(in[x].x);
            out[3 * x + 1] = toByte(in[x].y);
            out[3 * x + 2] = toByte(in[x].z);
        }
    }
    std::unique_lock<std::mutex> lock(mutex_);
    for (int y = y0; y < y1; ++y) rowReady_[size_t(y)] = 1;
    while (readyPrefix_ < bytes_.height && rowReady_[size_t(readyPrefix_)]) ++readyPrefix_;
    // One thread compresses at a time; it looks again for ready rows before it stops, so rows
    // reported meanwhile are not left behind.
    if (encoding_ || error_) return;
    encoding_ = true;
    encodeReadyRows(lock);
    encoding_ = false;
}

// Called and returns with the lock held; compresses without it.
void PngStream::encodeReadyRows(std::unique_lock<std::mutex>& lock) {
    const int strategyRows = pngStrategyLastRow(bytes_.height) + 1;
    while (!error_) {
        const int from = encoded_, to = readyPrefix_;
        if (to == from || (!encoder_ && to < strategyRows)) return;
        lock.unlock();
        try {
            // pngZlibStrategy reads rows below strategyRows only: all final here.
            if (!encoder_)
                encoder_ = std::make_unique<PngRowEncoder>(bytes_.width, bytes_.height, 3, pngZlibStrategy(bytes_));
            for (int y = from; y < to; ++y) encoder_->row(bytes_.row(y));
        } catch (...) {
            lock.lock();
            error_ = std::current_exception();
            return;
        }
        lock.lock();
        encoded_ = to;
    }
}

std::vector<uint8_t> PngStream::finish() {
    std::unique_lock<std::mutex> lock(mutex_);
    if (!error_ && !encoding_) encodeReadyRows(lock);  // rows reported but not compressed (none normally)
    if (error_) std::rethrow_exception(error_);
    if (encoded_ != bytes_.height)
        throw Error("error: PNG encoder: " + std::to_string(bytes_.height - encoded_) + " rows were never given");
    return encoder_->finish();
}

}  // namespace rays
