#include "field/saved_run.h"

#include <cstdint>
#include <cstring>
#include <type_traits>
#include <vector>

#include <fmt/format.h>

#include "ir/source_loc.h"

namespace simeco::field {

namespace {

constexpr char kMagic[] = "simeco saved run\n";
// 2: a particle's fourth slot counts its seconds in deep shade (it was the cone noise's clock).
// 4: a plant of a batch after the first draws from the random stream of its place in the field (each batch had
// streams of its own), so a run saved before goes on otherwise.
// 5: the field's plants in one state, however it was batched (a batch's random streams step at every advance of
// the field, where they stepped only at those its plants derived in).
constexpr uint32_t kVersion = 5;

class Writer {
public:
    template <typename T>
    void put(const T& value) {
        static_assert(std::is_trivially_copyable_v<T>);
        bytes.append(reinterpret_cast<const char*>(&value), sizeof(T));
    }
    template <typename T>
    void put(const std::vector<T>& values) {
        static_assert(std::is_trivially_copyable_v<T>);
        put<uint64_t>(values.size());
        bytes.append(reinterpret_cast<const char*>(values.data()), values.size() * sizeof(T));
    }
    void put(const std::string& text) {
        put<uint64_t>(text.size());
        bytes += text;
    }
    std::string bytes;
};

class Reader {
public:
    Reader(const std::string& bytes, const std::string& name) : bytes_(bytes), name_(name) {}

    template <typename T>
    T get() {
        static_assert(std::is_trivially_copyable_v<T>);
        T value;
        std::memcpy(&value, take(sizeof(T)), sizeof(T));
        return value;
    }
    template <typename T>
    std::vector<T> getVector() {
        const uint64_t count = get<uint64_t>();
        if (count > (bytes_.size() - at_) / sizeof(T)) fail("it is truncated");
        std::vector<T> values(count);
        const char* bytes = take(count * sizeof(T));
        if (count > 0) std::memcpy(values.data(), bytes, count * sizeof(T));
        return values;
    }
    std::string getString() {
        const uint64_t size = get<uint64_t>();
        if (size > bytes_.size() - at_) fail("it is truncated");
        return std::string(take(size), size);
    }
    bool atEnd() const { return at_ == bytes_.size(); }
    [[noreturn]] void fail(const std::string& why) const {
        throw ir::InputError({name_, 0, 0}, fmt::format("not a state simeco can resume: {}", why));
    }

private:
    const char* take(size_t n) {
        if (n > bytes_.size() - at_) fail("it is truncated");
        const char* p = bytes_.data() + at_;
        at_ += n;
        return p;
    }
    const std::string& bytes_;
    const std::string& name_;
    size_t at_ = 0;
};

void putModules(Writer& w, const stream::ModuleString& s) {
    w.put<int32_t>(s.stride);
    w.put(s.sym);
    w.put(s.paramCount);
    w.put(s.params);
    w.put(s.particles);
    w.put(s.plantStart);
}

stream::ModuleString getModules(Reader& r) {
    stream::ModuleString s;
    s.stride = r.get<int32_t>();
    s.sym = r.getVector<uint32_t>();
    s.paramCount = r.getVector<uint8_t>();
    s.params = r.getVector<float>();
    s.particles = r.getVector<shared::ParticleState>();
    s.plantStart = r.getVector<uint64_t>();
    const size_t n = s.sym.size();
    bool consistent = s.stride >= 1 && s.paramCount.size() == n && s.params.size() == n * size_t(s.stride) &&
                      (s.particles.empty() || s.particles.size() == n) && !s.plantStart.empty() &&
                      s.plantStart.front() == 0 && s.plantStart.back() == n;
    for (size_t p = 1; consistent && p < s.plantStart.size(); ++p) consistent = s.plantStart[p - 1] <= s.plantStart[p];
    for (size_t i = 0; consistent && i < n; ++i) consistent = s.paramCount[i] <= s.stride;
    if (!consistent) r.fail("a derived string is inconsistent");
    return s;
}

} // namespace

std::string encodeSavedRun(const SavedRun& run) {
    Writer w;
    w.bytes = kMagic;
    w.put(kVersion);
    const SimulationOptions& o = run.options;
    w.put(o.file);
    w.put(o.sceneText);
    w.put(o.plants);
    w.put(o.density);
    w.put(o.seed);
    w.put(o.dt);
    w.put(o.spacing);
    const SimulationState& s = run.state;
    w.put(s.ticks);
    w.put(s.nextStep);
    w.put(s.plants.fieldStep);
    putModules(w, s.plants.string);
    w.put<uint64_t>(s.plants.plants.size());
    for (const stream::PlantVariables& v : s.plants.plants) {
        w.put(v.globals);
        w.put<uint64_t>(v.arrays.size());
        for (const std::vector<double>& a : v.arrays) w.put(a);
        w.put<uint8_t>(v.stopRequested);
        w.put<int32_t>(v.stepsDerived);
    }
    return w.bytes;
}

SavedRun decodeSavedRun(const std::string& bytes, const std::string& name) {
    Reader r(bytes, name);
    if (bytes.compare(0, sizeof(kMagic) - 1, kMagic) != 0) r.fail("it does not start as one");
    for (size_t k = 0; k + 1 < sizeof(kMagic); ++k) r.get<char>();
    const uint32_t version = r.get<uint32_t>();
    if (version != kVersion)
        r.fail(fmt::format("it is of version {}, this simeco reads version {}", version, kVersion));
    SavedRun run;
    SimulationOptions& o = run.options;
    o.file = r.getString();
    o.sceneText = r.getString();
    o.plants = r.get<uint32_t>();
    o.density = r.get<float>();
    o.seed = r.get<int64_t>();
    o.dt = r.get<float>();
    o.spacing = r.get<float>();
    SimulationState& s = run.state;
    s.ticks = r.get<uint32_t>();
    s.nextStep = r.getVector<float>();
    stream::SteppedState& b = s.plants;
    b.fieldStep = r.get<uint32_t>();
    b.string = getModules(r);
    const uint64_t plants = r.get<uint64_t>();
    if (plants != b.string.plants()) r.fail("its plants do not match its string");
    if (plants != s.nextStep.size()) r.fail("its plants do not match their steps to come");
    for (uint64_t p = 0; p < plants; ++p) {
        stream::PlantVariables v;
        v.globals = r.getVector<double>();
        const uint64_t arrays = r.get<uint64_t>();
        if (arrays > bytes.size()) r.fail("it is truncated");
        for (uint64_t a = 0; a < arrays; ++a) v.arrays.push_back(r.getVector<double>());
        v.stopRequested = r.get<uint8_t>() != 0;
        v.stepsDerived = r.get<int32_t>();
        b.plants.push_back(std::move(v));
    }
    if (!r.atEnd()) r.fail("it has bytes past its end");
    if (!(o.dt > 0)) r.fail("its tick is not positive");
    if (!(o.density > 0)) r.fail("its population density is not positive");
    return run;
}

} // namespace simeco::field
