#include "kernels/kernel_parameters.hpp"

#include <stdexcept>

namespace iblkit::kernels {

NamedValues PrefilterParameters::members() const { return {{"Roughness", {roughness}}}; }

NamedValues PrefilterChunkParameters::members() const {
    return {{"Roughness", {roughness}},
            {"FirstSample", {double(firstSample)}},
            {"ChunkSamples", {double(chunkSamples)}},
            {"Resolve", {resolve ? 1.0 : 0.0}}};
}

NamedValues PrefilterTableParameters::members() const { return {{"SampleCount", {double(sampleCount)}}}; }

NamedValues PrefilterPyramidParameters::members() const {
    if (lods.size() != weights.size() || lods.empty() || lods.size() > 4)
        throw std::invalid_argument("PrefilterPyramidCS takes 1 to 4 reads, each a lod and a weight");
    std::vector<double> lodsOf(4, 0.0), weightsOf(4, 0.0);
    for (size_t i = 0; i < lods.size(); ++i) {
        lodsOf[i] = lods[i];
        weightsOf[i] = weights[i];
    }
    return {{"ReadLods", lodsOf}, {"ReadWeights", weightsOf}};
}

NamedValues PrefilterRingParameters::members() const {
    return {{"Ring", {centreLod, ringLod, cosAngle, centreWeight}}};
}

NamedValues LutGridParameters::members() const { return {{"GridSize", {double(gridSize)}}}; }

NamedValues ClusterParameters::members() const { return {{"Level", {double(level)}}}; }

NamedValues PrefilterConvolutionParameters::members() const {
    return {{"Roughness", {roughness}},
            {"TopLevel", {double(topLevel)}},
            {"FineLevel", {double(fineLevel)}},
            {"Refine", {refine}},
            {"HorizonLevel", {double(horizonLevel)}},
            {"Weighting", {double(weighting)}}};
}

NamedValues BrdfChunkParameters::members() const {
    return {{"FirstSample", {double(firstSample)}},
            {"ChunkSamples", {double(chunkSamples)}},
            {"Resolve", {resolve ? 1.0 : 0.0}}};
}

NamedValues SupersampleParameters::members() const { return {{"Supersample", {double(supersample)}}}; }

NamedValues SourceMipParameters::members() const { return {{"SourceMip", {double(sourceMip)}}}; }

NamedValues IrradianceParameters::members() const { return {{"MomentSize", {double(momentSize)}}}; }

void IblRecipeParameters::addTo(NamedValues& values) const {
    values.insert({{"SpecularSize", {double(specularSize)}}, {"LodMapping", {double(lodMapping)}},
                   {"LodParameter", {lodParameter}},         {"Direction", {double(direction)}},
                   {"Lookup", {double(lookup)}},             {"LightCount", {double(lightCount)}},
                   {"LightLevel", {double(lightLevel)}}});
}

NamedValues PreviewParameters::members() const {
    NamedValues values{{"Columns", {double(columns)}},           {"Rows", {double(rows)}},
                       {"CellSize", {double(cellSize)}},         {"SpecularMips", {double(specularMips)}},
                       {"StripPanelWidth", {double(stripPanelWidth)}}, {"Exposure", {exposure}}};
    recipe.addTo(values);
    return values;
}

NamedValues RenderReferenceParameters::members() const {
    return {{"Columns", {double(columns)}},         {"CellSize", {double(cellSize)}},
            {"FirstSample", {double(firstSample)}},
            {"SampleCount", {double(sampleCount)}}, {"Seed", {double(seed)}},
            {"LightCount", {double(lightCount)}},   {"DistributionSize", {double(distributionSize)}},
            {"EnvironmentMip", {double(environmentMip)}}, {"ActiveCount", {double(activeCount)}}};
}

NamedValues RenderSplitSumParameters::members() const {
    NamedValues values{{"Columns", {double(columns)}}, {"CellSize", {double(cellSize)}}, {"SpecularMips", {double(specularMips)}},
                       {"GlassTransmission", {double(glassTransmission)}}, {"GlassRoughnessScale", {double(glassRoughnessScale)}}};
    recipe.addTo(values);
    return values;
}

NamedValues ProbeParameters::members() const { return {{"ArgumentCount", {double(argumentCount)}}}; }

} // namespace iblkit::kernels
