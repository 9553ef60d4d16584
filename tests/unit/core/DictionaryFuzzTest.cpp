// Randomised robustness test of the dictionary parser, built with AddressSanitizer and
// UndefinedBehaviorSanitizer: every valid fixture, and generated seeds for what the fixtures do
// not reach (include chains and loops, doubling macros, #includeEtc names that try to leave the
// etc directory), is mutated (byte deletions, insertions of syntax characters, duplications,
// truncations) and parsed. Each parse must end in a Dictionary or an mfdyn::Error; a crash, a
// sanitizer report or any other exception fails, and so does an error message that is long (a
// message quotes excerpts, not files) or quotes the contents of the file outside etc/.
//
// Usage: coreDictionaryFuzzAsan [mutants per fixture, default 5000]; the generated seeds scale
// with it. The default runs in about 20-30 s with the sanitizers.
#include "core/Dictionary.hpp"

#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <random>
#include <sstream>

namespace fs = std::filesystem;

namespace {

std::string readText(const fs::path& p) {
    std::ifstream in(p, std::ios::binary);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

std::string mutate(std::string text, std::mt19937& rng) {
    static const std::string syntax = "{}();$#\"/*\\\n e.-+";
    const int edits = 1 + int(rng() % 4);
    for (int k = 0; k < edits; ++k) {
        const std::size_t at = text.empty() ? 0 : rng() % (text.size() + 1);
        switch (rng() % 6) {
            case 0:  // delete a byte
                if (at < text.size()) text.erase(at, 1);
                break;
            case 1:  // insert a syntax character
            case 2:
                text.insert(at, 1, syntax[rng() % syntax.size()]);
                break;
            case 3: {  // duplicate a span
                const std::size_t len = rng() % 16;
                text.insert(at, text.substr(at, len));
                break;
            }
            case 4:  // truncate
                text.resize(at);
                break;
            case 5:  // an arbitrary byte, including non-ASCII and NUL
                text.insert(at, 1, char(rng() % 256));
                break;
        }
    }
    return text;
}

// The two lines of the file outside the etc directory that the #includeEtc seeds aim at.
const std::string firstLine = "FIRST-LINE-OF-A-FILE-OUTSIDE-ETC", secondLine = "SECOND-LINE-OF-IT";

// One text to mutate, read as the file `name` (so relative #include names resolve beside it).
struct Seed {
    fs::path name;
    std::string text;
    int mutants;
    std::string expect;                  // unmutated: "ok" parses, else the error says this
    std::vector<std::string> forbidden;  // no message may quote these
};

// Seeds for the limits: written into `dir` with the files they include.
std::vector<Seed> generatedSeeds(const fs::path& dir, int perFixture) {
    std::vector<Seed> seeds;
    // A chain of includes past the depth limit of 64, and a shorter one within it.
    for (int i = 0; i < 70; ++i)
        std::ofstream(dir / ("chain" + std::to_string(i)))
            << "k" << i << " " << i << ";\nsub" << i << " { x 1; }\n#include \"chain" << i + 1 << "\"\n";
    std::ofstream(dir / "chain70") << "end 1;\n";
    seeds.push_back({dir / "chain0",
                     readText(dir / "chain0"),
                     perFixture / 10,
                     "included files nested deeper than 64",
                     {}});
    seeds.push_back({dir / "chain20", readText(dir / "chain20"), perFixture / 10, "ok", {}});
    // Loops: a -> b -> a, and a file that includes itself inside a dictionary.
    std::ofstream(dir / "loopA") << "a 1;\n#include \"loopB\"\n";
    std::ofstream(dir / "loopB") << "b { c 2; }\n#include \"loopA\"\n";
    seeds.push_back({dir / "loopA", readText(dir / "loopA"), perFixture / 2, "include loop", {}});
    std::ofstream(dir / "self") << "s { #include \"self\" } t 1;\n";
    seeds.push_back({dir / "self", readText(dir / "self"), perFixture / 2, "include loop", {}});
    // Doubling macros: 8 levels stay inside the copy limit (mutations duplicate macros, so they
    // grow); 40 levels reach it, at the cost of a million copies a parse (seconds with ASan).
    std::string doubling = "m0 1 2;\nd0 { a 1; }\n";
    for (int i = 1; i <= 40; ++i) {
        const std::string p = std::to_string(i - 1), n = std::to_string(i);
        doubling += "m" + n + " ($m" + p + " $m" + p + ");\nd" + n + " { x $d" + p + "; y $d" + p + "; }\n";
        if (i == 8) seeds.push_back({dir / "doubling8", doubling, perFixture / 3, "ok", {}});
    }
    seeds.push_back({dir / "doubling40", doubling, 2, "past the limit of 1000000", {}});
    // Nesting through macros, past 200 levels.
    std::string nesting = "n0 1;\n";
    for (int i = 1; i <= 210; ++i)
        nesting += "n" + std::to_string(i) + " ($n" + std::to_string(i - 1) + ");\n";
    seeds.push_back({dir / "nesting", nesting, perFixture / 10, "nesting deeper than 200 levels", {}});
    // #includeEtc: inside, and out through '..', an absolute path and a symbolic link.
    fs::create_directories(dir / "etc" / "materials");
    std::ofstream(dir / "etc" / "materials" / "steel") << "rho0 7850;\nE 200e9;\n";
    std::ofstream(dir / "outside") << firstLine << "\n" << secondLine << " 1 2 3\n";
    fs::create_symlink(dir / "outside", dir / "etc" / "materials" / "link");
    const std::string outside = (dir / "outside").string();
    seeds.push_back(
        {dir / "etcInside", "steel { #includeEtc \"materials/steel\" E 210e9; }\n", perFixture, "ok", {}});
    seeds.push_back({dir / "etcEscape",
                     "a { #includeEtc \"../outside\" }\nb { #includeEtc \"materials/../../outside\" }\n"
                     "c { #includeEtc \"" +
                         outside + "\" }\nd { #includeEtc \"materials/link\" }\n",
                     perFixture,
                     "a '..' component",
                     {firstLine, secondLine}});
    seeds.push_back({dir / "etcLink",
                     "d { #includeEtc \"materials/link\" }\n",
                     perFixture / 10,
                     "outside the etc directory",
                     {firstLine, secondLine}});
    // A plain #include may read any file: its parse error quotes an excerpt of the offending
    // line (the first line, the key whose value has no ';'), not the file.
    seeds.push_back({dir / "includeOutside",
                     "x { #include \"" + outside + "\" }\n",
                     perFixture / 2,
                     "expected ';' after the value of '" + firstLine + "'",
                     {secondLine}});
    return seeds;
}

}  // namespace

int main(int argc, char** argv) {
    const auto start = std::chrono::steady_clock::now();
    const std::clock_t cpuStart = std::clock();
    const fs::path dir = MFDYN_FIXTURE_DIR;
    const int perFixture = argc > 1 ? std::atoi(argv[1]) : 5000;
    std::mt19937 rng(20240611u);
    int fixtures = 0, parsed = 0, errors = 0;
    std::size_t longestMessage = 0;

    std::vector<Seed> seeds;
    std::vector<fs::path> files;
    for (const auto& f : fs::directory_iterator(dir))
        if (f.path().extension() == ".dict") files.push_back(f.path());
    std::sort(files.begin(), files.end());
    for (const auto& file : files) {
        std::string text = readText(file);
        if (text.find("expect-error") != std::string::npos) continue;
        ++fixtures;
        seeds.push_back({file, std::move(text), perFixture, "ok", {}});
    }
    const fs::path work = fs::temp_directory_path() / ("mfdynFuzz" + std::to_string(::getpid()));
    fs::remove_all(work);
    fs::create_directories(work);
    for (auto& s : generatedSeeds(work, perFixture)) seeds.push_back(std::move(s));

    mfdyn::ReadOptions options;
    options.etcDirectories = {work / "etc", dir / "etc"};
    int status = 0;
    for (const Seed& seed : seeds) {
        const std::clock_t seedStart = std::clock();
        // The seed itself, then its mutants.
        for (int i = -1; i < seed.mutants && status == 0; ++i) {
            const std::string text = i < 0 ? seed.text : mutate(seed.text, rng);
            std::string problem;
            try {
                const mfdyn::Dictionary d = mfdyn::Dictionary::parse(text, seed.name.string(), options);
                // Printing must give text that parses again.
                mfdyn::Dictionary::parse(d.str(), "printed", options);
                ++parsed;
                if (i < 0 && seed.expect != "ok")
                    problem = "the seed parsed; expected \"" + seed.expect + "\"";
            } catch (const mfdyn::Error& e) {
                ++errors;
                const std::string message = e.what();
                longestMessage = std::max(longestMessage, message.size());
                // The longest messages list include chains, shortened, and loops of at most 64
                // files; anything longer quotes more than an excerpt.
                if (message.size() > 8000)
                    problem = "a message of " + std::to_string(message.size()) + " bytes";
                for (const auto& f : seed.forbidden)
                    if (message.find(f) != std::string::npos) problem = "the message quotes '" + f + "'";
                if (i < 0 && message.find(seed.expect) == std::string::npos)
                    problem = "the seed's error does not say \"" + seed.expect + "\"";
                if (!problem.empty()) problem += "\n--- message ---\n" + message.substr(0, 2000);
            } catch (const std::exception& e) {
                std::cerr << "FAIL: " << seed.name.filename() << " mutation " << i
                          << " threw a non-mfdyn exception: " << e.what() << "\n--- input ---\n"
                          << text << "\n---\n";
                status = 1;
            }
            if (!problem.empty()) {
                std::cerr << "FAIL: " << seed.name.filename() << " mutation " << i << ": " << problem
                          << "\n--- input ---\n"
                          << text.substr(0, 4000) << "\n---\n";
                status = 1;
            }
        }
        const double cpu = double(std::clock() - seedStart) / CLOCKS_PER_SEC;
        if (cpu > 1.0)
            std::cout << seed.name.filename() << ": " << seed.mutants << " mutants in " << cpu << " s CPU\n";
    }
    fs::remove_all(work);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    const double cpu = double(std::clock() - cpuStart) / CLOCKS_PER_SEC;
    std::cout << fixtures << " fixtures and " << seeds.size() - std::size_t(fixtures) << " generated seeds, "
              << parsed << " texts parsed, " << errors << " rejected with errors (longest message "
              << longestMessage << " bytes), in " << seconds << " s (" << cpu << " s CPU)\n";
    if (status) return status;
    if (fixtures < 20 || parsed == 0 || errors == 0) {
        std::cerr << "FAIL: the mutations did not exercise both outcomes\n";
        return 1;
    }
    return 0;
}
