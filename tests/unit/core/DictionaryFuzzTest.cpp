// Randomised robustness test of the dictionary parser, built with AddressSanitizer and
// UndefinedBehaviorSanitizer: every valid fixture is mutated thousands of times (byte deletions,
// insertions of syntax characters, duplications, truncations) and parsed. Each parse must end in
// a Dictionary or an mfdyn::Error; a crash, a sanitizer report or any other exception fails.
#include "core/Dictionary.hpp"

#include <algorithm>
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

}  // namespace

int main(int argc, char** argv) {
    const fs::path dir = MFDYN_FIXTURE_DIR;
    const int perFixture = argc > 1 ? std::atoi(argv[1]) : 3000;
    std::mt19937 rng(20240611u);
    int fixtures = 0, parsed = 0, errors = 0;
    std::vector<fs::path> files;
    for (const auto& f : fs::directory_iterator(dir))
        if (f.path().extension() == ".dict") files.push_back(f.path());
    std::sort(files.begin(), files.end());
    for (const auto& file : files) {
        const std::string original = readText(file);
        if (original.find("expect-error") != std::string::npos) continue;
        mfdyn::ReadOptions options;
        options.etcDirectories = {dir / "etc"};
        ++fixtures;
        for (int i = 0; i < perFixture; ++i) {
            const std::string text = mutate(original, rng);
            try {
                const mfdyn::Dictionary d = mfdyn::Dictionary::parse(text, file.string(), options);
                // Printing must give text that parses again.
                mfdyn::Dictionary::parse(d.str(), "printed", options);
                ++parsed;
            } catch (const mfdyn::Error&) {
                ++errors;
            } catch (const std::exception& e) {
                std::cerr << "FAIL: " << file.filename() << " mutation " << i
                          << " threw a non-mfdyn exception: " << e.what() << "\n--- input ---\n"
                          << text << "\n---\n";
                return 1;
            }
        }
    }
    std::cout << fixtures << " fixtures, " << parsed << " mutants parsed, " << errors
              << " rejected with errors\n";
    if (fixtures < 20 || parsed == 0 || errors == 0) {
        std::cerr << "FAIL: the mutations did not exercise both outcomes\n";
        return 1;
    }
    return 0;
}
