// PngStream: PNG encoding that runs while the image is still being rendered. The render reports
// rows as they are finished (in any order, from any thread); each report quantises its rows to
// 8 bits, and whichever thread reports finds the next rows in order ready compresses them, so the
// compression shares the render's threads instead of following the render. The result is the
// same file, byte for byte, as writeImage(".png") of the finished image gives.
#pragma once
#include <cstdint>
#include <exception>
#include <memory>
#include <mutex>
#include <vector>

#include "rays/image/image.h"
#include "rays/io/image_io.h"

namespace rays {

class PngStream {
public:
    PngStream(int width, int height);

    /// Rows [y0, y1) of img (top row first, img the full-size image) are final. Thread-safe; each
    /// row is reported once. Never throws: an encoder failure is reported by finish().
    void rowsDone(const ImageF& img, int y0, int y1);

    /// The PNG file's bytes once every row has been reported; throws rays::Error otherwise or when
    /// encoding failed.
    std::vector<uint8_t> finish();

private:
    void encodeReadyRows(std::unique_lock<std::mutex>& lock);

    Image8 bytes_;                            ///< quantised rows (each written by the thread reporting it)
    std::vector<uint8_t> rowReady_;           ///< per row, guarded by mutex_
    int readyPrefix_ = 0;                     ///< rows [0, readyPrefix_) are all ready (mutex_)
    int encoded_ = 0;                         ///< rows given to the encoder (mutex_ or the encoding thread)
    bool encoding_ = false;                   ///< a thread is compressing (mutex_)
    std::unique_ptr<PngRowEncoder> encoder_;  ///< made once the rows pngZlibStrategy reads are ready
    std::exception_ptr error_;
    std::mutex mutex_;
};

}  // namespace rays
