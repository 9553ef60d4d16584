// particleGen: particles from system/particleGenDict, written to 0/particles.vtp.
#include "core/Application.hpp"
#include "core/Case.hpp"
#include "core/CaseLock.hpp"
#include "core/LibraryLoader.hpp"
#include "core/Log.hpp"
#include "geometry/ParticleGenerator.hpp"
#include "particles/PvdIndex.hpp"
#include "particles/TimeDirectory.hpp"

#include <filesystem>

int main(int argc, char** argv) {
    const mfdyn::ApplicationInfo info{
        "particleGen",
        "Generate particles from system/particleGenDict into 0/particles.vtp.\n\n"
        "Initial fields a region's `fields { ... }` may set (any other name is an error):\n" +
            mfdyn::ParticleGenerator::knownFieldsHelp() +
            "A field that a model of your own reads is declared at the top of particleGenDict with\n"
            "`userFields (name1 name2);`. See libraries/geometry/ParticleGenerator.hpp.",
        {},
        {},
        true};
    return mfdyn::runApplication(argc, argv, info, [](const mfdyn::Arguments& args) {
        using namespace mfdyn;
        Case runCase(args.caseDir());
        Log::info(banner("particleGen", runCase.root(), args.commandLine()));
        // 0/ and particles.pvd are rewritten: not under a solver that is running on the case.
        const CaseLock lock(runCase.root(), "particleGen");
        const auto controlDictPath = runCase.systemFile("controlDict");
        if (std::filesystem::exists(controlDictPath))
            LibraryLoader::load(Dictionary::read(controlDictPath), runCase.root());
        const Dictionary dict = runCase.readSystem("particleGenDict");
        ParticleGenerator generator(dict);
        const auto particles = generator.generate();
        for (const auto& u : dict.unusedEntries())
            Log::warning(u.where.str() + ": '" + u.scopedKey + "' was never read" +
                         (u.suggestion.empty() ? "" : " (did you mean '" + u.suggestion + "'?)"));
        // Times computed from the previous 0/ no longer follow from it: moved aside, so that
        // startFrom latestTime does not resume from them.
        std::vector<std::string> later;
        for (const auto& t : runCase.timeDirectories())
            if (t.value > 0) later.push_back(t.name);
        if (!later.empty())
            Log::info("Moved " + std::to_string(later.size()) +
                      " time directories computed from the previous initial conditions to " +
                      moveAsideTimeDirectories(runCase.root(), later).string() + "/");
        writeTimeDirectory(runCase.root(), "0", *particles, {}, 0.0);
        PvdIndex pvd(runCase.root() / "particles.pvd");
        pvd.add(0.0, std::string("0/") + particleFileName);
        pvd.write();
        Log::info(generator.reportTable());
        Log::info("Wrote " + std::to_string(particles->size()) + " particles (" +
                  std::to_string(particles->dimension()) + "D) to " +
                  (runCase.root() / "0" / particleFileName).string());
        return 0;
    });
}
