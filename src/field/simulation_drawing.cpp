// The growing field drawn: every batch interpreted with its organs at their particles' sizes, given the light of
// the last drawing's grid and splatted into it for the next, with each plant's statistics.

#include "field/simulation_impl.h"

namespace simeco::field {

std::vector<const turtle::DeviceOrgans*> Simulation::Impl::interpretOnDevice() {
    if (!turtle) turtle = std::make_unique<turtle::GpuTurtle>(*context, commands, turtles);
    if (!batches.front().statistics) {
        const std::vector<float> areas = leafShapeAreas(g.assets.models);
        for (Batch& b : batches) b.statistics = std::make_unique<GpuPlantStatistics>(*context, areas);
    }
    const bool merged = batches.size() > 1 || hasObstacles();
    if (merged) organMerge().begin();
    lastStatistics.clear();
    // The batches whose drawn strings stand draw again, every one in one submission with the light grid's
    // clearing and, where every batch draws again, its propagation, each into organ buffers of its own: the host
    // reads nothing between them, and after them only their statistics, their organs' tables and whether each fit
    // its room. Where all fit, that is the drawing of the whole field.
    std::vector<uint8_t> again(batches.size(), 0);
    uint32_t modules = 0, plants = 0; // the largest string and plants of them
    turtle::TurtleRoom room;
    for (size_t k = 0; k < batches.size(); ++k) {
        const Batch& b = batches[k];
        if (!drawsAgain(b)) continue;
        again[k] = 1;
        modules = std::max({modules, b.deriver->lastDrawn().count, 1u});
        plants = std::max(plants, b.count);
        room.levels = std::max(room.levels, b.room->levels);
    }
    std::vector<std::optional<stream::DeviceModules>> drawnAgain(batches.size());
    Clock::time_point start = Clock::now();
    if (modules > 0) turtle->reserveTargets(modules, plants, room);
    const bool everyBatch = std::find(again.begin(), again.end(), 0) == again.end();
    context->submitAndWait([&](VkCommandBuffer cmd) {
        recordGrowthWaiting(cmd); // the last tick's: a tick between steps and its drawing are one submission
        lightGpu->recordClear(cmd);
        for (size_t k = 0; k < batches.size(); ++k)
            if (again[k]) drawnAgain[k] = recordDrawingAgain(cmd, batches[k]);
        if (everyBatch) lightGpu->recordPropagate(cmd);
    });
    seconds.interpret += secondsSince(start) - growthRecorded();
    uint64_t firstModule = 0;
    const turtle::DeviceOrgans* organs = nullptr;
    reinterpreted = 0;
    for (size_t k = 0; k < batches.size(); ++k) {
        Batch& b = batches[k];
        const std::optional<turtle::RecordedInterpretation> found =
            again[k] ? std::optional(turtle::GpuTurtle::recordedInto(b.target)) : std::nullopt;
        const bool fit = found && found->fit;
        reinterpreted += fit ? 0 : 1;
        if (fit) { // the string drawn again until the next step needs no more than it found
            b.room->levels = found->levels;
            b.room->marks = found->marks;
            b.roomGuessed = false;
        }
        // Else, or where it outgrew its room, the batch is drawn with the host reading between the turtle's passes.
        const Drawing drawing = fit ? Drawing{*drawnAgain[k], &b.target.organs} : drawInterpreting(b, drawnAgain[k]);
        organs = drawing.organs;
        start = Clock::now();
        const std::vector<shared::PlantStatistics> s = b.statistics->read();
        lastStatistics.insert(lastStatistics.end(), s.begin(), s.end());
        seconds.statistics += secondsSince(start);
        start = Clock::now();
        if (merged) merge->keepInPlace(*organs, b.statistics->organTable(), b.first, firstModule);
        firstModule += drawing.modules.count;
        seconds.interpret += secondsSince(start);
    }
    // The batches drawn after it gathered the light before (recordPropagate()); their organs are propagated too.
    if (!everyBatch || reinterpreted > 0) {
        const Clock::time_point lightStart = Clock::now();
        context->submitAndWait([&](VkCommandBuffer cmd) { lightGpu->recordPropagate(cmd); });
        seconds.light += secondsSince(lightStart);
    }
    lightGpu->turn();
    if (!merged) return {organs};
    start = Clock::now();
    if (hasObstacles()) merge->keep(obstacleOrganBuffers(), derive.plants, firstModule);
    std::vector<const turtle::DeviceOrgans*> parts = merge->mergeParts();
    seconds.interpret += secondsSince(start);
    return parts;
}

stream::DeviceModules Simulation::Impl::recordDrawingAgain(VkCommandBuffer cmd, Batch& b) {
    // The string as the homomorphism wrote it, with the particles the tick grew.
    b.deriver->recordDrawnAgain(cmd);
    stream::DeviceModules modules = b.deriver->lastDrawn();
    // A grammar without a homomorphism draws its derived string: its segments shorten a copy.
    if (tables.growsSegments() && modules.symbols == b.deriver->current().symbols)
        modules = b.growth->recordCopyForDrawing(cmd, modules);
    if (growsSizes()) b.growth->recordSizes(cmd, modules, drawingSettings(b));
    recordLight(cmd, b, modules, turtle->recordInto(cmd, modules, b.field, *b.room, b.target));
    return modules;
}

Simulation::Impl::Drawing Simulation::Impl::drawInterpreting(Batch& b,
                                                             std::optional<stream::DeviceModules> drawnAgain) {
    Clock::time_point start = Clock::now();
    stream::DeviceModules modules;
    if (drawnAgain) {
        modules = *drawnAgain; // sized already: a segment shortened twice would be short
    } else {
        modules = b.deriver->drawn();
        if (tables.growsSegments() && modules.symbols == b.deriver->current().symbols)
            modules = b.growth->copyForDrawing(modules);
        if (growsSizes()) b.growth->growSizes(modules, drawingSettings(b));
    }
    const turtle::DeviceOrgans& organs = turtle->interpret(modules, b.field);
    b.room = turtle->lastRoom();
    b.room->marks = turtle->lastMarks(); // the string this batch draws again until it derives
    b.roomGuessed = false;
    seconds.interpret += secondsSince(start);
    start = Clock::now();
    context->submitAndWait([&](VkCommandBuffer cmd) {
        recordLight(cmd, b, modules, organs);
        turtle->recordKeep(cmd, b.target);
    });
    seconds.statistics += secondsSince(start);
    return {modules, &b.target.organs};
}

void Simulation::Impl::recordLight(VkCommandBuffer cmd, Batch& b, const stream::DeviceModules& modules,
                                   const turtle::DeviceOrgans& organs) {
    if (modules.particles && !splatsOnly)
        lightGpu->recordGather(cmd, organs, *modules.particles, modules.origins, b.deriver->current().particles,
                               b.first);
    if (answersQueries && !splatsOnly) {
        const stream::DeviceModules derived = b.deriver->current();
        lightGpu->recordQueries(cmd, turtle->lastModuleStates(), modules.count,
                                modules.symbols == derived.symbols ? nullptr : modules.origins, *derived.symbols,
                                *derived.params, derived.stride);
    }
    b.statistics->record(cmd, organs, modules.particles, baseHeights(b.field.placements));
    lightGpu->recordSplat(cmd, organs, b.first);
}

const turtle::DeviceOrgans& Simulation::Impl::obstacleOrganBuffers() {
    if (!obstacles.instances) obstacles = turtle::uploadOrgans(*context, obstacleOrgans(g.scene->obstacles));
    return obstacles;
}

std::vector<const turtle::DeviceOrgans*> Simulation::Impl::interpretOnHost() {
    Clock::time_point start = Clock::now();
    // The batches' drawn strings one after the other: the field's.
    stream::ModuleString field;
    field.plantStart.push_back(0);
    // Where each batch's drawn modules start in the field's, and the module of its derived string each comes from.
    std::vector<size_t> drawnStarts;
    std::vector<std::vector<uint32_t>> origins(batches.size());
    for (Batch& b : batches) {
        drawnStarts.push_back(field.size());
        stream::ModuleString drawnModules = b.reference->drawn(&origins[drawnStarts.size() - 1]);
        if (growsSizes()) grow::growSizesCpu(drawingSettings(b), b.deriveTimes, drawnModules);
        if (b.first == 0) field.stride = drawnModules.stride; // the batches' species, and so their strides, alike
        field.append(drawnModules, 0, drawnModules.size());
        for (size_t p = 1; p < drawnModules.plantStart.size(); ++p)
            field.plantStart.push_back(field.plantStart[b.first] + drawnModules.plantStart[p]);
    }
    turtle::FieldOptions where;
    where.placements = placements;
    const turtle::Interpretation organs = turtle::interpretCpu(field, commands, turtles, where);
    seconds.interpret += secondsSince(start);
    start = Clock::now();
    const std::vector<float> shapeAreas = leafShapeAreas(g.assets.models);
    // The light goes to the drawn modules' particles and to those of the derived modules they come from.
    auto derivedOf = [&](uint32_t module) -> shared::ParticleState* {
        const size_t k = size_t(std::upper_bound(drawnStarts.begin(), drawnStarts.end(), size_t(module)) -
                                drawnStarts.begin()) - 1;
        const std::vector<uint32_t>& from = origins[k];
        const size_t j = module - drawnStarts[k];
        return j < from.size() ? &batches[k].reference->current().particles[from[j]] : nullptr;
    };
    if (!splatsOnly) lightCpu->gather(organs, field.particles, derivedOf);
    if (answersQueries && !splatsOnly) answerQueriesOnHost(field, drawnStarts, origins);
    seconds.light += secondsSince(start);
    start = Clock::now();
    lastStatistics = plantStatisticsCpu(organs, baseHeights(placements), field.particles, shapeAreas);
    seconds.statistics += secondsSince(start);
    start = Clock::now();
    lightCpu->clear();
    lightCpu->splat(organs, shapeAreas);
    lightCpu->propagate();
    seconds.light += secondsSince(start);
    uploaded = turtle::uploadOrgans(*context, organs);
    if (!hasObstacles()) return {&uploaded};
    organMerge().begin();
    merge->keep(uploaded, 0, 0);
    merge->keep(obstacleOrganBuffers(), derive.plants, field.size());
    return merge->mergeParts();
}

void Simulation::Impl::answerQueriesOnHost(const stream::ModuleString& field, const std::vector<size_t>& drawnStarts,
                                           const std::vector<std::vector<uint32_t>>& origins) {
    for (const turtle::EnvironmentQuery& q : turtle::environmentQueries(field, commands, turtles)) {
        const size_t k = size_t(std::upper_bound(drawnStarts.begin(), drawnStarts.end(), q.module) -
                                drawnStarts.begin()) - 1;
        const size_t j = q.module - drawnStarts[k];
        if (j >= origins[k].size()) continue;
        stream::ModuleString& derived = batches[k].reference->current();
        const size_t to = origins[k][j];
        const shared::PlantPlacement& m = placements[q.plant];
        const glm::vec4 l = lightCpu->lightAt(turtle::placePoint(m, q.position));
        // light_queries.comp's answer: the light as a share of the open's, its direction in the plant's frame.
        const glm::vec3 toward = glm::normalize(turtle::turnIntoPlant(m, glm::vec3(l)));
        const float answer[4] = {openLight > 0.0f ? l.w / openLight : 1.0f, toward.x, toward.y, toward.z};
        const uint32_t count = derived.paramCount[to];
        for (uint32_t a = 0; a < std::min(count, count >= 4 ? 4u : 1u); ++a)
            derived.params[to * size_t(derived.stride) + a] = answer[a];
    }
}

std::vector<const turtle::DeviceOrgans*> Simulation::interpretParts() {
    Impl& m = *impl_;
    if (!m.context) throw std::logic_error("Simulation::interpret: drawing needs a Vulkan device");
    m.prepareLight(grownBounds(), standingPlants());
    std::vector<const turtle::DeviceOrgans*> parts =
        m.options.backend == Backend::Gpu ? m.interpretOnDevice() : m.interpretOnHost();
    m.drawn = true;
    return parts;
}

const turtle::DeviceOrgans& Simulation::interpret() {
    const std::vector<const turtle::DeviceOrgans*> parts = interpretParts();
    if (parts.size() > 1)
        throw ir::LimitError(fmt::format("the field's organs come in {} parts, more than one buffer binding holds",
                                         parts.size()));
    return *parts.front();
}

std::vector<shared::PlantStatistics> Simulation::statistics() const {
    if (!impl_->drawn) throw std::logic_error("Simulation::statistics before interpret() after the last tick");
    return impl_->lastStatistics;
}

std::vector<draw::OrganPart> organParts(const std::vector<const turtle::DeviceOrgans*>& parts) {
    std::vector<draw::OrganPart> drawn;
    for (const turtle::DeviceOrgans* part : parts) drawn.push_back({&part->instances, &part->table});
    return drawn;
}

} // namespace simeco::field
