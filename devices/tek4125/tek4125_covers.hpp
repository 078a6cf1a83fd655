#pragma once
// Covers of a progressive 4125 stream: RR rectangles that show a blocky
// picture early, in levels of finer bands (16 rows, then 8), each level
// painting only where it brings the screen nearer the picture.
//
// Method, per band of a level: for every column, the sums over the band's
// rows of the target colours (the palette colours the final screen shows),
// of their squares, and of the squared error of what the screen shows now.
// A dynamic programme over the columns picks segments either left as they
// are (their current error) or painted as one rectangle the band's height in
// the palette entry nearest the segment's mean colour (which minimises the
// summed squared error among the entries: sum |t - c|^2 = S2 - 2 c.S1 +
// n |c|^2), minimising error + lambda * rectangle bytes, lambda in
// proportion to the band's height: a level of half the height refines at
// half the price, so the steepest gains in error a byte come first. A cover from the
// band's average rather than from one of its rows: a row through a hair
// paints the hair's colour over seven rows that do not hold it. Later
// levels start from what the earlier ones showed, so they refine rather
// than repaint. Cut points are where a column's band differs from the
// previous column's; a rectangle spans at most kCoverWindow of them.
//
// Tunables: kCoverLevels (band heights), kCoverLambdaPerRow, kCoverWindow.
#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "devices/tek4125/tek4125_rows.hpp"
#include "devices/tek4125/tek4125_writer.hpp"
#include "foundation/scanline.hpp"

namespace lattice::tek4125 {

// Plate 6 at 512x512, the stream after 25 % of its bytes: 16 and 8 rows
// with draft rows after them (tek4125_progressive.hpp) 23.6 dB; 8, 4 and 2
// rows 23.2 dB and 4 % more bytes (bench/strict-quality.sh).
inline constexpr std::array<int, 2> kCoverLevels = {16, 8};
inline constexpr double kCoverLambdaPerRow = 2000.0;  // squared error a byte is worth, per row of band
inline constexpr int kCoverWindow = 64;

// The colour a pixel showing device index `device` has (-1: the page's
// clear, entry 0; an entry outside the picture's: black).
Rgb8 colourShown(const Palette& palette, int device, int reserved);

// One cover: image columns x0..x1 and rows y0..y1 (inclusive, row 0 the
// top), filled with device index `device`.
struct CoverRectangle {
  int x0 = 0, x1 = 0, y0 = 0, y1 = 0, device = 0;
};

// Chooses the covers, band heights `levels` in turn, of a width x height
// picture. pixels: palette indices, row-major; fullXy: the form set's (a
// rectangle's bytes); shown: the device index each pixel shows before (-1:
// the page's clear), updated with every rectangle chosen.
std::vector<CoverRectangle> planCovers(int width, int height, bool fullXy, std::span<const PaletteIndex> pixels,
                                       const Palette& palette, int reserved, std::vector<int>& shown,
                                       std::span<const int> levels = kCoverLevels);

// Sends the covers as RR commands and paints them into shown (the layout's size).
void sendCovers(Tek4125Writer& out, const Tek4125RowLayout& layout, std::span<const CoverRectangle> covers,
                std::vector<int>& shown);

}  // namespace lattice::tek4125
