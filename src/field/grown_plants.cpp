#include "field/grown_plants.h"

#include <algorithm>
#include <cmath>

#include "compute/shared/growth_layout.h"
#include "cpu/derive.h"
#include "grow/tick_cpu.h"
#include "ir/species.h"
#include "turtle/turtle_cpu.h"

namespace simeco::field {

double latestGrowth(const std::vector<ir::Grammar>& species, const grow::GrowthTables& tables,
                    const std::vector<float>& deriveTimes, int fixedSteps) {
    float longestGrowth = 0;
    for (size_t r = 0; r < tables.rows.size(); r += shared::kStageRowFloats)
        longestGrowth = std::max(longestGrowth, tables.rows[r + shared::propertyMax(shared::kGrowTime)]);
    double latest = 0;
    for (uint32_t p = 0; p < deriveTimes.size(); ++p) {
        const ir::Grammar& g = species[ir::speciesOfPlant(p, species.size())];
        latest = std::max(latest, double(deriveTimes[p]) * (fixedSteps >= 0 ? fixedSteps : g.derivationLength));
    }
    return latest + longestGrowth;
}

GrownPlants growOneOfEach(const grow::GrowingSpecies& g, const grow::GrowthTables& tables,
                          const stream::DeriveOptions& derive, uint32_t seed, const std::vector<float>& deriveTimes,
                          double until, const turtle::TurtleCommands& commands,
                          const std::vector<turtle::TurtleSettings>& turtles) {
    stream::DeriveOptions one = derive;
    one.plants = uint32_t(g.species.size());
    one.absent.clear(); // one plant of each species, whatever slots the field leaves empty
    one.lightScale = 0.0f; // each grows alone, in the open: light() is 1
    cpu::SteppedDerivation plants(g.species, one);
    std::vector<float> times(deriveTimes.begin(), deriveTimes.begin() + std::min(deriveTimes.size(), g.species.size()));
    times.resize(one.plants, grow::kDefaultDeriveTime);
    std::vector<float> next = times;
    grow::TickSettings ts{&tables, one.plants, std::max(0.25f, *std::min_element(times.begin(), times.end()) / 2), 0,
                          seed, g.relativeGravity()};
    auto modulesOf = [](const stream::ModuleString& s, uint32_t p) { return s.plantStart[p + 1] - s.plantStart[p]; };
    std::vector<uint64_t> firstSteps(one.plants);
    std::vector<size_t> steps(one.plants, 0);
    for (uint32_t p = 0; p < one.plants; ++p) firstSteps[p] = modulesOf(plants.current(), p);
    for (double t = 0; t < until + ts.dt; t += ts.dt, ++ts.tick) {
        std::vector<uint8_t> due(one.plants, 0);
        bool any = false;
        for (uint32_t p = 0; p < one.plants; ++p)
            if (t + ts.dt >= next[p]) due[p] = 1, next[p] += times[p], any = true;
        if (any) plants.advance(due); // the random streams step with the steps, as the field's do
        for (uint32_t p = 0; p < one.plants; ++p)
            if (due[p] && ++steps[p] <= kFirstSteps) firstSteps[p] = modulesOf(plants.current(), p);
        grow::tickCpu(ts, plants.current());
    }
    stream::ModuleString drawn = plants.drawn();
    if (tables.drawsGrowth() || tables.growsSegments()) grow::growSizesCpu(ts, times, drawn);
    GrownPlants grown;
    grown.bounds.resize(one.plants);
    for (uint32_t p = 0; p < one.plants; ++p) {
        grown.drawnModules.push_back(modulesOf(drawn, p));
        const double drawnToDerived =
            std::max(1.0, double(modulesOf(drawn, p)) / double(std::max<uint64_t>(modulesOf(plants.current(), p), 1)));
        grown.firstStepsModules.push_back(uint64_t(std::ceil(double(firstSteps[p]) * drawnToDerived)));
    }
    const turtle::Interpretation organs = turtle::interpretCpu(drawn, commands, turtles, {});
    for (const shared::OrganInstance& o : organs.organs) {
        const turtle::Bounds box = turtle::organBounds(o);
        grown.bounds[o.plant].add(box.min - organs.plantOrigins[o.plant]);
        grown.bounds[o.plant].add(box.max - organs.plantOrigins[o.plant]);
    }
    return grown;
}

} // namespace simeco::field
