// Every corpus scene (and seed 003's textured and shadowed scenes) compared with the oracle at 1 and 16 samples per pixel (and at 1 with back faces culled): no
// genuine disagreement, except known divergences listed with a reason in corpus/expectations/oracle.txt (an entry
// that no longer diverges fails), and every excuse class within its cap.
#include <filesystem>

#include <gtest/gtest.h>

#include "harness/comparison/comparison_output.h"
#include "harness/comparison/excuse_account.h"
#include "oracle/compare/expectations.h"
#include "raster/compat/scene_loader.h"

namespace raster::oracle {
namespace {

namespace fs = std::filesystem;

const fs::path kSource = RASTER_SOURCE_DIR;

struct CorpusCase {
    fs::path scene;
    int samples;
    bool cull_back = false;  // also every scene with back-face culling forced on, at 1 sample
    // The name the expectations file uses: the stem, with "/cull-back" for the culled variant.
    std::string name() const { return scene.stem().string() + (cull_back ? "/cull-back" : ""); }
};

std::vector<CorpusCase> corpus_cases() {
    std::vector<fs::path> scenes;
    for (const auto& entry : fs::directory_iterator(kSource / "corpus/scenes"))
        if (entry.is_regular_file()) scenes.push_back(entry.path());
    std::sort(scenes.begin(), scenes.end());
    // The seed 003 scenes with a texture from its OBJ's material, and with shadows, in the course's own format.
    scenes.push_back(kSource / "corpus/seeds/003/textured.json");
    scenes.push_back(kSource / "corpus/seeds/003/shadows.json");
    std::vector<CorpusCase> cases;
    for (const fs::path& scene : scenes)
        for (int samples : {1, 16}) cases.push_back({scene, samples});
    for (const fs::path& scene : scenes) cases.push_back({scene, 1, true});
    return cases;
}

void PrintTo(const CorpusCase& c, std::ostream* os) { *os << c.name() << " at " << c.samples << " spp"; }

class CorpusAgainstOracle : public ::testing::TestWithParam<CorpusCase> {};

TEST_P(CorpusAgainstOracle, hasNoGenuineDisagreement) {
    const CorpusCase& c = GetParam();
    Scene scene = load_scene(c.scene);
    scene.settings.samples = c.samples;
    if (c.cull_back) scene.settings.cull_backfaces = true;
    const harness::Comparison comparison = harness::compare_scene(scene, harness::ComparisonOptions{});
    const std::vector<KnownDivergence> known = load_expectations(kSource / "corpus/expectations/oracle.txt");
    const KnownDivergence* expected = find_expectation(known, c.name(), c.samples);
    const uint64_t genuine = comparison.genuine_total();
    const ComparisonCounts& counts = comparison.visibility.counts;
    RecordProperty("genuine_total", std::to_string(genuine));
    RecordProperty("ambiguous_total", std::to_string(counts.ambiguous_total()));
    if (expected) {
        EXPECT_GT(genuine, 0u) << "oracle.txt:" << expected->line << " lists a divergence that is gone: remove it";
        EXPECT_LE(genuine, expected->max_genuine) << harness::comparison_summary(comparison) << "known: " << expected->reason;
    } else {
        EXPECT_EQ(genuine, 0u) << harness::comparison_summary(comparison);
    }
    // Every sample is classed, and every excuse class (the four sample classes in samples and in pixels, wide
    // colour intervals, the shadow and transparency models' open pixels) stays within its cap (excuse_account.h).
    uint64_t total = 0;
    for (uint64_t n : counts.by_class) total += n;
    EXPECT_EQ(total, comparison.raster.visibility.size());
    const harness::ExcuseAccount excuses = harness::account_excuses(comparison);
    EXPECT_TRUE(excuses.within()) << excuses.violations() << harness::comparison_summary(comparison);
}

std::string case_name(const ::testing::TestParamInfo<CorpusCase>& info) {
    std::string name = info.param.scene.stem().string() + "_" + std::to_string(info.param.samples) + "spp" +
                       (info.param.cull_back ? "_cull_back" : "");
    for (char& ch : name)
        if (!std::isalnum(static_cast<unsigned char>(ch))) ch = '_';
    return name;
}

INSTANTIATE_TEST_SUITE_P(Corpus, CorpusAgainstOracle, ::testing::ValuesIn(corpus_cases()), case_name);

TEST(CorpusExpectations, theCheckedInFileParses) {
    EXPECT_NO_THROW(load_expectations(kSource / "corpus/expectations/oracle.txt"));
}

}  // namespace
}  // namespace raster::oracle
