// A plant's skeleton drawn in three orthogonal views, the way the L-grammar generator's thesis (seed 002, section
// 3.2) picks stems from photographs: each stem a 2D polyline in the front, the side and the top view, the three
// matched by stem id, and combined into 3D. The views read from a JSON or an SVG file (docs/SKELETON.md).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include <glm/vec2.hpp>

#include "ir/source_loc.h"
#include "skeleton/skeleton.h"

namespace simeco::skeleton {

// One stem as one view shows it: its points (u, v) in world units, from its base to its tip.
struct ViewStem {
    int id = 0;
    std::optional<int> parent; // the front view's: -1 on the ground; none where the file does not say
    double width = 0.0;        // the front view's
    std::vector<glm::dvec2> points;
    ir::SourceLoc where; // where the file draws it, for errors (line 0 where unknown)
};

struct View {
    std::vector<ViewStem> stems;
};

// The world axes each view shows as (u, v), as a drawing's views are laid out: front (x, y) seen along -z, side
// (z, y) seen along +x, top (x, -z) seen from above with the front at the bottom. Each pair of views shares one
// axis: front and side y, front and top x, side and top z.
struct ThreeViews {
    View front, side, top;
};

// The exact orthographic projections of `plant`'s stems (every view gets each stem's id, parent and width).
ThreeViews projectThreeViews(const Plant& plant);

// The 3D plant the views draw. A stem's points, where its three polylines have as many points, pair by index,
// each coordinate the mean of the two views that show it; otherwise they are resampled (three_views.cpp says
// how). Parent and width come from the front view; where no front stem gives a parent, parents are found from
// where the stems touch (linkStemsByGeometry, within kSnapFraction of the plant's size). A stem's base drawn
// within kSnapFraction of its parent (a parentless one: of the plant's base) is moved onto it, since drawn views
// never meet exactly. Refuses, naming the stem, a stem missing from a view or drawn twice in one, a view without
// points, and views that disagree by more than kDisagreementFraction of the plant's size on a shared coordinate
// of a stem's base or tip (a polyline drawn from tip to base, or views with different origins). The stems'
// structure is checked by checkSkeleton.
Plant plantFromThreeViews(const ThreeViews& views, const std::string& file);

// How far, as a fraction of the plant's size, a stem's base may be drawn from its parent and still be taken to
// start on it: points picked by hand on photographs are a few pixels off, a stem drawn farther off is a mistake
// that checkPlant reports.
inline constexpr double kSnapFraction = 0.02;
// How far two views may disagree on the coordinate they share at a stem's base or tip: more than drawing errors,
// less than a polyline turned around or a view drawn with its own origin.
inline constexpr double kDisagreementFraction = 0.05;

// The JSON form: {"views": {"front": {"stems": [{"id": 0, "parent": -1, "width": w, "points": [[u, v], ...]},
// ...]}, "side": {...}, "top": {...}}}, parent and width written in the front view only.
std::string threeViewsJson(const ThreeViews& views);

// The SVG form: the three views side by side (front, side, then top), each a group of polylines with their stem
// ids (data-stem) and, in the front view, parents and widths, for tracing over photographs or editing.
std::string threeViewsSvg(const ThreeViews& views);

// Reads the JSON form; `file` names it in errors (text that is not JSON at its line and column, a value of the
// wrong shape by its JSON pointer). A stem's "parent" and "width" are read from the front view; both may be left
// out (no parent: see plantFromThreeViews; width 0).
Skeleton parseThreeViewsJson(const std::string& text, const std::string& file);

// Reads an SVG drawing: three groups <g id="front">, <g id="side"> and <g id="top">, each holding one
// <polyline points="..."> or <path d="..."> per stem, with attributes data-stem="id" and, in the front view,
// optional data-parent="id" and data-width="w". Paths use M, L, H and V (absolute or relative); curves, a closed
// path and transforms are refused. SVG's y grows downward, so a view's v is the SVG's -y. Shapes without
// data-stem are decoration and skipped. Errors at their line and column.
Skeleton parseThreeViewsSvg(const std::string& text, const std::string& file);

// Reads the views at `path`: a .json or an .svg file.
Skeleton readThreeViews(const std::string& path);

} // namespace simeco::skeleton
