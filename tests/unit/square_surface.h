// A cpfg surface file for tests: one flat patch, a square four units on a side in the file's x-y plane from (0, 0)
// to (4, 4), its contact point at (2, 0), its end at (2, 4), its heading +y and its up -z (the frame of cpfg's
// leaves), its size 4. `precision` is put where a PRECISION line goes.
#pragma once

#include <string>

namespace simeco::testing {

inline std::string squareSurface(const std::string& precision = "") {
    std::string text = "0 4  0 4  0 0\n" + precision +
                       "CONTACT POINT  X: 2 Y: 0 Z: 0\n"
                       "END POINT  X: 2 Y: 4 Z: 0\n"
                       "HEADING  X: 0 Y: 1 Z: 0\n"
                       "UP  X: 0 Y: 0 Z: -1\n"
                       "SIZE: 4\n"
                       "square\n"
                       "TOP COLOR: 0 DIFFUSE: 0.00 BOTTOM COLOR: 0 DIFFUSE: 0.00\n"
                       "AL: ~ A: ~ AR: ~\nL: ~ R: ~\nBL: ~ B: ~ BR: ~\n";
    for (int row = 0; row < 4; ++row) {
        for (int column = 0; column < 4; ++column)
            text += std::to_string(4 * column / 3.0) + " " + std::to_string(4 * row / 3.0) + " 0  ";
        text += "\n";
    }
    return text;
}

} // namespace simeco::testing
