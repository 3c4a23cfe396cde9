// The filters the bench runs, as designed on the host (bilinear transform, fs = 1 kHz,
// fc = 30 Hz, the gyro low-pass of a typical rate loop). Written out because the Butterworth
// design is another module's job; the bench only needs realistic coefficient values.
#pragma once

namespace bench {

// b0, b1, a1 of the 1st-order low-pass.
inline constexpr double kLowpass1[] = {0.0863640270, 0.0863640270, -0.8272719460};

// b0, b1, b2, a1, a2 of the 2nd-order Butterworth low-pass.
inline constexpr double kLowpass2[] = {0.0078202080, 0.0156404161, 0.0078202080, -1.7347257688, 0.7660066009};

}  // namespace bench
