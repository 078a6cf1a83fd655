#include "devices/tek4027/tek4027_encoder.hpp"

#include <fmt/format.h>

#include <array>
#include <iterator>

#include "devices/tek4027/tek4027_pacing.hpp"
#include "foundation/name_table.hpp"

namespace lattice::tek4027 {

namespace {
constexpr std::array<EnumName<Tek4027Strategy>, 7> kStrategyNames = {{
    {Tek4027Strategy::RowOrder, "row-order"},
    {Tek4027Strategy::ColourOrder, "colour-order"},
    {Tek4027Strategy::Chained, "chained"},
    {Tek4027Strategy::ChainedRelative, "chained-relative"},
    {Tek4027Strategy::Layered, "layered"},
    {Tek4027Strategy::LayeredChained, "layered-chained"},
    {Tek4027Strategy::Shortest, "shortest"},
}};
constexpr std::array<EnumName<Tek4027Orientation>, 3> kOrientationNames = {{
    {Tek4027Orientation::Rows, "rows"},
    {Tek4027Orientation::RowsUp, "rows-up"},
    {Tek4027Orientation::Columns, "columns"},
}};
}  // namespace

std::string_view strategyName(Tek4027Strategy strategy) { return nameOfValue(kStrategyNames, strategy, "?"); }
std::string_view orientationName(Tek4027Orientation orientation) {
  return nameOfValue(kOrientationNames, orientation, "?");
}

int percentFromLevel(std::uint8_t level) { return (level * 100 + 127) / 255; }
std::uint8_t levelFromPercent(long percent) { return static_cast<std::uint8_t>((percent * 255 + 50) / 100); }

namespace {

// Spells commands. Between commands no terminator is written: the next
// command character ends a command on the terminal, which saves a byte each.
class CommandWriter {
 public:
  CommandWriter(std::string& out, const Tek4027Profile& profile, Tek4027StreamStats& stats)
      : out_(out), profile_(profile), stats_(stats) {}

  void command(const char* name) {
    out_ += profile_.commandChar;
    out_ += name;
    firstArg_ = true;
    ++stats_.commands;
  }
  void arg(long value) {
    separate();
    fmt::format_to(std::back_inserter(out_), "{}", value);
  }
  void arg(const char* text) {
    separate();
    out_ += text;
  }
  void pot(int n) {
    separate();
    out_ += 'C';
    out_ += static_cast<char>('0' + n);
  }
  void end() { out_ += profile_.terminator; }

 private:
  // The name is always followed by a space (it must be delimited from a
  // first argument that could start with a letter, e.g. "C3").
  void separate() {
    out_ += firstArg_ ? ' ' : profile_.separator;
    firstArg_ = false;
  }

  std::string& out_;
  const Tek4027Profile& profile_;
  Tek4027StreamStats& stats_;
  bool firstArg_ = true;
};

class Encoder {
 public:
  Encoder(const Tek4027Picture& picture, const Tek4027Profile& profile, Tek4027StreamStats& stats)
      : picture_(picture), frame_(picture.frame), profile_(profile), stats_(stats), w_(out_, profile, stats) {}
  // Another orientation: `frame` is the picture turned (orientedFrame());
  // every point is turned back when it is written.
  Encoder(const Tek4027Picture& picture, const PotFrame& frame, Tek4027Orientation orientation,
          const Tek4027Profile& profile, Tek4027StreamStats& stats)
      : picture_(picture), frame_(frame), profile_(profile), stats_(stats), w_(out_, profile, stats),
        orientation_(orientation) {}

  std::string run(Tek4027Strategy strategy) {
    preamble();
    switch (strategy) {
      case Tek4027Strategy::RowOrder: rowOrder(); break;
      case Tek4027Strategy::ColourOrder: colourOrder(); break;
      case Tek4027Strategy::Chained: chained(false, false); break;
      case Tek4027Strategy::ChainedRelative: chained(true, false); break;
      case Tek4027Strategy::Layered: layered(); break;
      case Tek4027Strategy::LayeredChained: chained(true, true); break;
      case Tek4027Strategy::Shortest: break;  // resolved by the caller
    }
    w_.end();
    return std::move(out_);
  }

 private:
  // Terminal coordinates of a point of the working frame: y counts up from
  // the bottom of the graphics area; a turned frame is turned back.
  struct TermPoint {
    long x, y;
  };
  TermPoint term(FramePoint p) const {
    int imageX = p.x, imageY = p.y;
    if (orientation_ == Tek4027Orientation::RowsUp) imageY = picture_.frame.height - 1 - p.y;
    if (orientation_ == Tek4027Orientation::Columns) std::swap(imageX, imageY);
    return {imageX, static_cast<long>(profile_.height) - 1 - imageY};
  }
  void point(CommandWriter& w, FramePoint p) const {
    const TermPoint t = term(p);
    w.arg(t.x);
    w.arg(t.y);
  }

  void preamble() {
    w_.command("WOR");
    w_.arg(profile_.workspaceLines);
    w_.command("GRA");
    w_.arg(profile_.graphicsFirstRow);
    w_.arg(profile_.graphicsLastRow);
    // Pots first, so the erase already shows the new background colour.
    for (int p = 0; p < 8; ++p) {
      const auto& rgb = picture_.potColours[static_cast<std::size_t>(p)];
      if (!rgb) continue;
      if (profile_.colourForm == Tek4027ColourForm::Mix) {
        w_.command("MIX");
        w_.pot(p);
        w_.arg(percentFromLevel(rgb->r));
        w_.arg(percentFromLevel(rgb->g));
        w_.arg(percentFromLevel(rgb->b));
      } else {
        const Hls hls = rgbToTekHls(*rgb);
        w_.command("MAP");
        w_.pot(p);
        w_.arg(hls.hue);
        w_.arg(hls.lightness);
        w_.arg(hls.saturation);
      }
    }
    w_.command("ERA");
    w_.arg("G");
  }

  void select(int pot) {
    if (pot == currentPot_) return;
    w_.command("COL");
    w_.pot(pot);
    currentPot_ = pot;
    ++stats_.colourSelects;
  }

  void vector(const PotRun& r) {
    w_.command("VEC");
    point(w_, {r.x0, r.y});
    point(w_, {r.x1, r.y});
    ++stats_.vectorCommands;
  }

  void rowOrder() {
    for (int y = 0; y < frame_.height; ++y)
      for (const PotRun& r : rowRuns(frame_, y)) {
        select(r.pot);
        vector(r);
      }
  }

  void colourOrder() {
    std::array<std::vector<PotRun>, 8> byPot;
    for (int y = 0; y < frame_.height; ++y)
      for (const PotRun& r : rowRuns(frame_, y)) byPot[static_cast<std::size_t>(r.pot)].push_back(r);
    for (int p = 0; p < 8; ++p) {
      if (byPot[static_cast<std::size_t>(p)].empty()) continue;
      select(p);
      for (const PotRun& r : byPot[static_cast<std::size_t>(p)]) vector(r);
    }
  }

  // A long chain is cut into commands of at most maxPointsPerCommand points;
  // each piece starts where the last ended, so the picture is unchanged.
  std::string absoluteChain(const std::vector<FramePoint>& chain, std::uint64_t& commands) {
    std::string text;
    Tek4027StreamStats scratch;
    CommandWriter w(text, profile_, scratch);
    const auto limit = static_cast<std::size_t>(profile_.maxPointsPerCommand);
    std::size_t inCommand = limit;
    for (std::size_t i = 0; i < chain.size(); ++i) {
      if (inCommand == limit) {
        w.command("VEC");
        inCommand = 0;
        if (i > 0) {
          point(w, chain[i - 1]);
          ++inCommand;
        }
      }
      point(w, chain[i]);
      ++inCommand;
    }
    commands = scratch.commands;
    return text;
  }

  // First segment absolute (it positions the beam), the rest as deltas:
  // !RVE continues from the beam, so a long chain is several !RVE commands.
  // Each starts with the pair `0 0`, as the font tool's does: whether the
  // first pair of !RVE moves the beam or draws is not settled, and a zero
  // pair moves nowhere or draws the pixel the beam already lit.
  std::string relativeChain(const std::vector<FramePoint>& chain, std::uint64_t& commands) {
    std::string text;
    Tek4027StreamStats scratch;
    CommandWriter w(text, profile_, scratch);
    w.command("VEC");
    for (std::size_t i = 0; i < 2; ++i) point(w, chain[i]);
    const auto deltas = static_cast<std::size_t>(profile_.maxPointsPerCommand) - 1;  // after the zero pair
    for (std::size_t i = 2; i < chain.size(); ++i) {
      if ((i - 2) % deltas == 0) {
        w.command("RVE");
        w.arg(0L);
        w.arg(0L);
      }
      const TermPoint a = term(chain[i - 1]), b = term(chain[i]);
      w.arg(b.x - a.x);
      w.arg(b.y - a.y);
    }
    commands = scratch.commands;
    return text;
  }

  // Pots in drawing order, each with the pots it may paint over (drawn later).
  std::vector<std::pair<int, unsigned>> drawingOrder(bool layered) const {
    std::vector<std::pair<int, unsigned>> order;
    if (!layered) {
      for (int p = 0; p < 8; ++p)
        if (p != frame_.backgroundPot) order.emplace_back(p, 0u);
      return order;
    }
    unsigned later = 0;
    const std::vector<int> pots = layerOrder(frame_);
    for (int p : pots) later |= 1u << p;
    for (int p : pots) {
      later &= ~(1u << p);
      order.emplace_back(p, later);
    }
    return order;
  }

  std::vector<std::vector<PotRun>> spansByRow(int pot, unsigned coverable) const {
    std::vector<std::vector<PotRun>> rows(static_cast<std::size_t>(frame_.height));
    for (int y = 0; y < frame_.height; ++y) rows[static_cast<std::size_t>(y)] = coverRuns(frame_, y, pot, coverable);
    return rows;
  }

  void layered() {
    for (const auto& [pot, coverable] : drawingOrder(true))
      for (const auto& row : spansByRow(pot, coverable))
        for (const PotRun& r : row) {
          select(pot);
          vector(r);
        }
  }

  void chained(bool relative, bool layered) {
    ChainOptions options;
    options.enterInterior = relative;
    for (const auto& [p, coverable] : drawingOrder(layered)) {
      auto chains = chainRuns(spansByRow(p, coverable), options);
      if (chains.empty()) continue;
      select(p);
      for (const auto& chain : chains) {
        std::uint64_t commands = 0;
        std::string text = absoluteChain(chain, commands);
        if (relative && profile_.relativeVectors && chain.size() > 2) {
          std::uint64_t altCommands = 0;
          std::string alt = relativeChain(chain, altCommands);
          if (alt.size() < text.size()) {
            text = std::move(alt);
            commands = altCommands;
          }
        }
        out_ += text;
        stats_.commands += commands;
        stats_.vectorCommands += commands;
      }
    }
  }

  const Tek4027Picture& picture_;
  const PotFrame& frame_;
  const Tek4027Profile& profile_;
  Tek4027StreamStats& stats_;
  std::string out_;
  CommandWriter w_;
  Tek4027Orientation orientation_ = Tek4027Orientation::Rows;
  int currentPot_ = -1;
};

// The picture as the encoder walks it: its rows bottom first (RowsUp), or
// its columns left first as rows (Columns).
PotFrame orientedFrame(const PotFrame& f, Tek4027Orientation orientation) {
  PotFrame t;
  const bool columns = orientation == Tek4027Orientation::Columns;
  t.width = columns ? f.height : f.width;
  t.height = columns ? f.width : f.height;
  t.backgroundPot = f.backgroundPot;
  t.pots.resize(f.pots.size());
  for (int y = 0; y < f.height; ++y)
    for (int x = 0; x < f.width; ++x) {
      const int tx = columns ? y : x, ty = columns ? x : f.height - 1 - y;
      t.pots[static_cast<std::size_t>(ty) * static_cast<std::size_t>(t.width) + static_cast<std::size_t>(tx)] = f.at(x, y);
    }
  return t;
}

}  // namespace

namespace {

// One strategy in one orientation, unpaced; the stats count the stream as
// the profile would pace it.
std::string encodeUnpaced(const Tek4027Picture& picture, const Tek4027Profile& profile, Tek4027Strategy strategy,
                          Tek4027Orientation orientation, Tek4027StreamStats& stats) {
  stats = {};
  stats.strategy = strategy;
  stats.orientation = orientation;
  const bool turned = orientation != Tek4027Orientation::Rows;
  const PotFrame working = turned ? orientedFrame(picture.frame, orientation) : PotFrame{};
  std::string text = turned ? Encoder(picture, working, orientation, profile, stats).run(strategy)
                            : Encoder(picture, profile, stats).run(strategy);
  const std::vector<std::size_t> cuts = recordCuts(text, profile);
  stats.reportRequests = cuts.size();
  stats.commands += stats.reportRequests;
  stats.bytes = pacedSize(text, cuts, profile);
  stats.lineSeconds = transmitSeconds(stats.bytes, profile.line);
  stats.terminalSeconds = static_cast<double>(stats.bytes) / profile.terminalCharsPerSecond;
  return text;
}

}  // namespace

std::string encodeTek4027(const Tek4027Picture& picture, const Tek4027Profile& profile, Tek4027Strategy strategy,
                          Tek4027StreamStats* stats, Tek4027Orientation orientation) {
  Tek4027StreamStats bestStats;
  std::string best;
  if (strategy == Tek4027Strategy::Shortest) {
    // Every strategy in every orientation (the same command forms; only the
    // runs' direction differs), compared by paced length: the shortest wins.
    for (auto o : {Tek4027Orientation::Rows, Tek4027Orientation::RowsUp, Tek4027Orientation::Columns})
      for (auto s : {Tek4027Strategy::RowOrder, Tek4027Strategy::ColourOrder, Tek4027Strategy::Chained,
                     Tek4027Strategy::ChainedRelative, Tek4027Strategy::Layered, Tek4027Strategy::LayeredChained}) {
        Tek4027StreamStats candidateStats;
        std::string candidate = encodeUnpaced(picture, profile, s, o, candidateStats);
        if (best.empty() || candidateStats.bytes < bestStats.bytes) {
          best = std::move(candidate);
          bestStats = candidateStats;
        }
      }
  } else {
    best = encodeUnpaced(picture, profile, strategy, orientation, bestStats);
  }
  if (stats != nullptr) *stats = bestStats;
  return paceWithReports(std::move(best), profile);
}

}  // namespace lattice::tek4027
