// apse demo — the comparison figure and the convergence plot.
// SPDX-License-Identifier: MIT
#pragma once

/// @file figures.hpp

#include <string>
#include <vector>

#include "image.hpp"

namespace demo {

/// One labelled panel of a comparison figure.
struct Panel {
    Canvas picture;
    std::string label, sublabel;
};

/// A grid of panels (`columns` per row), each with its label above: the picture at half
/// resolution (nearest-neighbour decimation, so noise looks as in the full image) and, beside
/// it, the region centred at `inset` (fractions of the image) at full resolution magnified
/// `zoom`×, outlined in the picture. `title` goes on top.
Canvas comparison_figure(const std::vector<Panel>& panels, int columns, glm::vec2 inset, int zoom,
                         const std::string& title);

/// One curve of the convergence plot.
struct Series {
    std::string name;
    rgb8 colour;
    std::vector<double> x, y;  // spp, relMSE
    bool dashed = false;       // drawn dashed on top (for a curve that coincides with another)
};

/// A log–log plot panel per entry of `plots` (title, curves) side by side, with axes, decade
/// ticks and one legend (every series name once).
Canvas convergence_plot(const std::vector<std::pair<std::string, std::vector<Series>>>& plots);

/// A distinct colour per sampler index.
rgb8 series_colour(int i);

}  // namespace demo
