#include "core/element/CongruentCells.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace vorodg {
namespace {

/// Coordinates relative to the cell's size quantized for hashing only: a class is decided by
/// comparing the coordinates themselves, so a rounding that splits two congruent cells costs
/// reuse, never correctness.
constexpr double kHashGrid = 1048576.0;  // 2^20

std::int64_t quantized(double v) {  // to nearest, half away from zero (inline, unlike floor)
  const double scaled = v * kHashGrid;
  return static_cast<std::int64_t>(scaled + (scaled >= 0.0 ? 0.5 : -0.5));
}

std::uint64_t mix(std::uint64_t h, std::int64_t v) {  // one multiply-xorshift round per value
  h = (h ^ static_cast<std::uint64_t>(v)) * 0x9e3779b97f4a7c15ull;
  return h ^ (h >> 29);
}

std::uint64_t hash_of(const std::vector<double>& key) {
  std::uint64_t h = 1469598103934665603ull;
  for (double v : key) h = mix(h, quantized(v));
  return h;
}

struct Frame {
  Point centroid;
  double size;
};

/// Every cell's centroid and size, once: the keys read them for each neighbour.
std::vector<Frame> frames_of(const PolygonMesh& mesh) {
  std::vector<Frame> frames(mesh.num_cells());
  for (int c = 0; c < mesh.num_cells(); ++c)
    frames[c] = {mesh.cell_centroid(c), std::sqrt(mesh.cell_area(c))};
  return frames;
}

/// Cell p's vertices relative to the frame, its loop started at its lowest vertex (x, then y,
/// quantized) so that the same polygon gives the same list whatever vertex its loop starts at.
void append_polygon(const PolygonMesh& mesh, int p, const Frame& f, std::vector<double>& key) {
  const auto loop = mesh.cell_vertices(p);
  const int n = static_cast<int>(loop.size());
  const std::size_t start = key.size() + 1;
  key.push_back(n);
  const double inverse = 1.0 / f.size;
  for (int v : loop) {
    const Point x = (mesh.vertex(v) - f.centroid) * inverse;
    key.push_back(x.x());
    key.push_back(x.y());
  }
  const auto lower = [&](int a, int b) {  // vertex a before vertex b
    const double* u = &key[start + 2 * a];
    const double* w = &key[start + 2 * b];
    return std::pair(quantized(u[0]), quantized(u[1])) <
           std::pair(quantized(w[0]), quantized(w[1]));
  };
  int first = 0;
  for (int k = 1; k < n; ++k)
    if (lower(k, first)) first = k;
  std::rotate(key.begin() + start, key.begin() + start + 2 * first, key.end());
}

/// The cell's own polygon in its frame (its loop as the mesh gives it: the shape functions are
/// numbered by it).
void shape_key(const PolygonMesh& mesh, const Frame& f, int c, std::vector<double>& key) {
  key.push_back(static_cast<double>(mesh.cell_size(c)));
  const double inverse = 1.0 / f.size;
  for (int v : mesh.cell_vertices(c)) {
    const Point x = (mesh.vertex(v) - f.centroid) * inverse;
    key.push_back(x.x());
    key.push_back(x.y());
  }
}

/// Buffers a key is built in, kept from cell to cell.
struct KeyScratch {
  std::vector<int> patch;
  std::vector<std::pair<std::pair<std::int64_t, std::int64_t>, int>> ordered;
  std::vector<double> key;
};

/// The shape key followed by every cell sharing a vertex with c, in the order of their
/// centroids' quantized offsets (a boundary shows as a cell missing from the list).
const std::vector<double>& neighbourhood_key(const PolygonMesh& mesh,
                                             const std::vector<Frame>& frames, int c,
                                             KeyScratch& s) {
  const Frame& f = frames[c];
  s.patch.clear();
  for (int v : mesh.cell_vertices(c))
    for (int p : mesh.vertex_cells(v))
      if (p != c) s.patch.push_back(p);
  std::sort(s.patch.begin(), s.patch.end());
  s.patch.erase(std::unique(s.patch.begin(), s.patch.end()), s.patch.end());
  s.ordered.clear();
  for (int p : s.patch) {
    const Point o = (frames[p].centroid - f.centroid) * (1.0 / f.size);
    s.ordered.push_back({{quantized(o.x()), quantized(o.y())}, p});
  }
  std::sort(s.ordered.begin(), s.ordered.end());
  s.key.clear();
  shape_key(mesh, f, c, s.key);
  s.key.push_back(static_cast<double>(s.ordered.size()));
  for (const auto& entry : s.ordered) append_polygon(mesh, entry.second, f, s.key);
  return s.key;
}

bool same_key(const std::vector<double>& a, const std::vector<double>& b, double tolerance) {
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i)
    if (!(std::abs(a[i] - b[i]) <= tolerance)) return false;
  return true;
}

}  // namespace

CongruentCells::CongruentCells(const PolygonMesh& mesh, double tolerance) {
  const int nc = mesh.num_cells();
  representative_.resize(nc);
  for (int c = 0; c < nc; ++c) representative_[c] = c;
  size_.assign(nc, 0);
  const std::vector<Frame> frames = frames_of(mesh);
  // First the cells' own polygons (cheap): a cell alone with its hash is a class of one, which
  // on an rcp mesh is nearly every cell.
  std::vector<std::pair<std::uint64_t, int>> by_shape(nc);
  KeyScratch scratch;
  for (int c = 0; c < nc; ++c) {
    scratch.key.clear();
    shape_key(mesh, frames[c], c, scratch.key);
    by_shape[c] = {hash_of(scratch.key), c};
  }
  std::sort(by_shape.begin(), by_shape.end());
  // Then, where polygons share a hash, their neighbourhoods: by hash again, and each candidate
  // checked against the representative's key itself, not only its hash.
  std::vector<std::pair<std::uint64_t, int>> by_neighbourhood;
  std::vector<std::pair<int, std::vector<double>>> found;  // representatives of one hash
  for (std::size_t first = 0; first < by_shape.size();) {
    std::size_t last = first + 1;
    while (last < by_shape.size() && by_shape[last].first == by_shape[first].first) ++last;
    by_neighbourhood.clear();
    for (std::size_t i = first; last - first > 1 && i < last; ++i) {
      const int c = by_shape[i].second;
      by_neighbourhood.push_back({hash_of(neighbourhood_key(mesh, frames, c, scratch)), c});
    }
    std::sort(by_neighbourhood.begin(), by_neighbourhood.end());
    for (std::size_t i = 0; i < by_neighbourhood.size(); ++i) {
      if (i == 0 || by_neighbourhood[i].first != by_neighbourhood[i - 1].first) found.clear();
      const int c = by_neighbourhood[i].second;
      const std::vector<double>& key = neighbourhood_key(mesh, frames, c, scratch);
      for (const auto& [r, r_key] : found)
        if (same_key(key, r_key, tolerance)) {
          representative_[c] = r;
          break;
        }
      if (representative_[c] == c) found.emplace_back(c, key);
    }
    first = last;
  }
  for (int c = 0; c < nc; ++c) ++size_[representative_[c]];
  for (int c = 0; c < nc; ++c) classes_ += representative_[c] == c;
}

}  // namespace vorodg
