#include "render/gi/photon_map.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <queue>
#include <utility>

namespace glint::render {

namespace {

constexpr char kPhotonMagic[8] = {'G', 'L', 'P', 'H', 'O', 'T', '0', '1'};

void put(std::ofstream& out, double v) { out.write(reinterpret_cast<const char*>(&v), sizeof v); }
bool get(std::ifstream& in, double* v) {
    return static_cast<bool>(in.read(reinterpret_cast<char*>(v), sizeof *v));
}

}  // namespace

void write_photon_file(const std::string& path, const std::vector<Photon>& surface,
                       const std::vector<Photon>& media, const FileLoc& at) {
    const std::string tmp = path + ".tmp";
    {
        std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
        if (!out) throw Error(ErrorKind::Output, at, "cannot write the photon file " + path);
        out.write(kPhotonMagic, sizeof kPhotonMagic);
        put(out, static_cast<double>(surface.size()));
        put(out, static_cast<double>(media.size()));
        for (const std::vector<Photon>* list : {&surface, &media})
            for (const Photon& ph : *list)
                for (double v : {ph.p.x, ph.p.y, ph.p.z, ph.to_source.x, ph.to_source.y,
                                 ph.to_source.z, ph.power.r, ph.power.g, ph.power.b})
                    put(out, v);
        if (!out.flush()) {
            std::remove(tmp.c_str());
            throw Error(ErrorKind::Output, at, "cannot write the photon file " + path);
        }
    }
    if (std::rename(tmp.c_str(), path.c_str()) != 0) {
        std::remove(tmp.c_str());
        throw Error(ErrorKind::Output, at, "cannot write the photon file " + path);
    }
}

void read_photon_file(const std::string& path, std::vector<Photon>* surface,
                      std::vector<Photon>* media, const FileLoc& at) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw Error(ErrorKind::MissingFile, at, "cannot read the photon file " + path);
    char magic[sizeof kPhotonMagic];
    double counts[2];
    if (!in.read(magic, sizeof magic) || std::memcmp(magic, kPhotonMagic, sizeof magic) != 0 ||
        !get(in, &counts[0]) || !get(in, &counts[1]))
        throw Error(ErrorKind::MissingFile, at,
                    path + " is not a photon file glint wrote (photons { save_file })");
    // Sizes the file itself can hold: a damaged count cannot ask for more memory than that.
    in.seekg(0, std::ios::end);
    const double room = static_cast<double>(in.tellg()) / (9 * sizeof(double));
    in.seekg(sizeof magic + 2 * sizeof(double));
    for (double c : counts)
        if (!(c >= 0 && c <= room && c == std::floor(c)))
            throw Error(ErrorKind::MissingFile, at, "the photon file " + path + " is damaged");
    std::vector<Photon>* lists[2] = {surface, media};
    for (int k = 0; k < 2; ++k) {
        lists[k]->clear();
        lists[k]->reserve(static_cast<size_t>(counts[k]));
        for (size_t i = 0; i < static_cast<size_t>(counts[k]); ++i) {
            double v[9];
            for (double& x : v)
                if (!get(in, &x))
                    throw Error(ErrorKind::MissingFile, at,
                                "the photon file " + path + " is cut short");
            Photon ph{Vec3(v[0], v[1], v[2]), Vec3(v[3], v[4], v[5]), Color(v[6], v[7], v[8])};
            bool finite = true;
            for (double x : v) finite = finite && std::isfinite(x);
            if (finite) lists[k]->push_back(ph);
        }
    }
}
namespace {

// photons.cpp: PhotonMap's gatherNumSteps (the adaptive gather widens at most once).
constexpr int kGatherSteps = 2;
// The "flattened" gather: a photon's squared distance grows by 16 times its share out of the
// surface's plane.
constexpr double kFlatten = 16;

double axis_of(const Vec3& v, int a) { return a == 0 ? v.x : a == 1 ? v.y : v.z; }

// splitmix64: the radius estimate's choice of sample photons, fixed by the seed.
uint64_t next_random(uint64_t* state) {
    uint64_t z = (*state += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
}

}  // namespace

PhotonMap::PhotonMap(std::vector<Photon> photons, const scene::Photons& settings, bool volume)
    : photons_(std::move(photons)), axis_(photons_.size(), 0), settings_(settings),
      volume_(volume) {
    if (volume_) {
        settings_.radius = settings.media_radius;
        settings_.radius_multiplier = settings.media_radius_multiplier;
    }
    // Photons somewhere non-finite, or with a non-finite power, would break the tree's order
    // and reach the image: they are dropped.
    std::erase_if(photons_, [](const Photon& ph) {
        return !std::isfinite(ph.p.x + ph.p.y + ph.p.z + ph.power.r + ph.power.g + ph.power.b);
    });
    axis_.assign(photons_.size(), 0);
    build(0, static_cast<uint32_t>(photons_.size()));
    estimate_radius();
}

void PhotonMap::build(uint32_t lo, uint32_t hi) {
    if (hi <= lo) return;
    const uint32_t mid = lo + (hi - lo) / 2;
    Vec3 a(kInfinity), b(-kInfinity);
    for (uint32_t i = lo; i < hi; ++i) {
        a = min(a, photons_[i].p);
        b = max(b, photons_[i].p);
    }
    const Vec3 e = b - a;
    const int axis = e.x >= e.y && e.x >= e.z ? 0 : e.y >= e.z ? 1 : 2;
    std::nth_element(photons_.begin() + lo, photons_.begin() + mid, photons_.begin() + hi,
                     [axis](const Photon& l, const Photon& r) {
                         return axis_of(l.p, axis) < axis_of(r.p, axis);
                     });
    axis_[mid] = static_cast<uint8_t>(axis);
    build(lo, mid);
    build(mid + 1, hi);
}

double PhotonMap::nearest(const Vec3& p, double size, const Vec3* n, int max_count,
                          std::vector<std::pair<double, uint32_t>>* heap) const {
    heap->clear();
    double dmax = size * size;
    if (max_count <= 0) return size;
    auto visit = [&](auto&& self, uint32_t lo, uint32_t hi) -> void {
        if (hi <= lo) return;
        const uint32_t mid = lo + (hi - lo) / 2;
        const Photon& ph = photons_[mid];
        const Vec3 v = ph.p - p;
        double d = dot(v, v);
        if (n) d += std::fabs(dot(*n, v)) * d * kFlatten;
        if (d < dmax) {
            if (static_cast<int>(heap->size()) < max_count) {
                heap->emplace_back(d, mid);
                std::push_heap(heap->begin(), heap->end());
            } else {
                // Full: the farthest makes way, and the search shrinks to the new farthest.
                std::pop_heap(heap->begin(), heap->end());
                heap->back() = {d, mid};
                std::push_heap(heap->begin(), heap->end());
                dmax = heap->front().first;
            }
        }
        const int axis = axis_[mid];
        const double delta = axis_of(p, axis) - axis_of(ph.p, axis);
        const uint32_t near_lo = delta < 0 ? lo : mid + 1, near_hi = delta < 0 ? mid : hi;
        const uint32_t far_lo = delta < 0 ? mid + 1 : lo, far_hi = delta < 0 ? hi : mid;
        self(self, near_lo, near_hi);
        if (delta * delta < dmax) self(self, far_lo, far_hi);
    };
    visit(visit, 0, static_cast<uint32_t>(photons_.size()));
    return std::sqrt(dmax);
}

void PhotonMap::gather(const Vec3& p, const Vec3* n, PhotonGather* out) const {
    out->photons.clear();
    out->radius = 0;
    if (photons_.empty() || !(radius_ > 0)) return;
    std::vector<std::pair<double, uint32_t>> heap, wider;
    double size = radius_;
    double r = nearest(p, size, n, settings_.gather_max, &heap);
    int num = static_cast<int>(heap.size());
    double prev = num / (r * r);
    if (prev == 0) prev = 1e-16;
    for (int step = 1; num < settings_.gather_min && step < kGatherSteps; ++step) {
        size += radius_step_;
        const double tr = nearest(p, size, n, settings_.gather_max, &wider);
        const int tn = static_cast<int>(wider.size());
        const double density = tn / (tr * tr);
        // Keep the wider gather while the density holds, or when it still found too few.
        if ((density - prev) / prev < settings_.expand_tolerance ||
            (tn < settings_.expand_min && tn > 0)) {
            prev = density == 0 ? 1e-16 : density;
            r = tr;
            num = tn;
            heap.swap(wider);
        } else {
            break;
        }
    }
    std::sort(heap.begin(), heap.end());
    for (const auto& [d, i] : heap) out->photons.push_back(&photons_[i]);
    out->radius = r;
}

double PhotonMap::density(size_t count, double r) const {
    return volume_ ? 3.0 * count / (4.0 * kPi * r * r * r) : count / (kPi * r * r);
}

void PhotonMap::estimate_radius() {
    // PhotonMap::setGatherOptions.
    if (settings_.radius > 0) {
        radius_ = settings_.radius;
    } else if (!photons_.empty()) {
        const size_t n = photons_.size();
        const size_t samples = std::clamp<size_t>(n / 20, 100, 1000);
        uint64_t rng = 0x5EED0F9407005ull;
        std::vector<std::pair<double, uint32_t>> heap;
        double sum = 0;
        for (size_t i = 0; i < samples; ++i) {
            const Vec3& at = photons_[next_random(&rng) % n].p;
            const double r = nearest(at, 10000000.0, nullptr, settings_.gather_max, &heap);
            // All photons at one point (radius 0): count the running average instead.
            sum += r > 0 ? density(heap.size(), r) : (i > 0 ? sum / i : 0.0);
        }
        const double average = sum / samples;
        radius_ = !(average > 0) ? 0.0
                  : volume_      ? std::pow(3.0 * settings_.gather_max / (average * kPi * 4.0), 0.3333)
                                 : std::sqrt(settings_.gather_max / (average * kPi));
        // Widen it where many places are sparser than the average.
        size_t sparse = 0;
        for (size_t i = 0; i < samples && radius_ > 0; ++i) {
            const Vec3& at = photons_[next_random(&rng) % n].p;
            const double r = nearest(at, radius_, nullptr, settings_.gather_max, &heap);
            if (r > 0) {
                const double d = density(heap.size(), r);
                if (d < average * 0.7 && d > average * 0.05) ++sparse;
            }
        }
        radius_ *= 1.0 + 20.0 * static_cast<double>(sparse) / samples;
    }
    radius_ *= settings_.radius_multiplier;
    if (volume_) radius_ *= 2;
    radius_step_ = 2 * radius_;
}

}  // namespace glint::render
