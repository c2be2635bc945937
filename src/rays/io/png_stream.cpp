#include "rays/io/png_stream.h"

#include "rays/error.h"

namespace rays {

PngStream::PngStream(int width, int height) : bytes_(width, height, 3), rowReady_(size_t(height), 0) {}

void PngStream::rowsDone(const ImageF& img, int y0, int y1) {
    const size_t width = size_t(img.width);
    toBytes(img.pixels.data() + size_t(y0) * width, size_t(y1 - y0) * width, bytes_.row(y0));
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
    // The thread that reported the last rows has compressed them.
    std::lock_guard<std::mutex> lock(mutex_);
    if (error_) std::rethrow_exception(error_);
    if (encoded_ != bytes_.height)
        throw Error("error: PNG encoder: " + std::to_string(bytes_.height - encoded_) + " rows were never given");
    return encoder_->finish();
}

}  // namespace rays
