// mfStudy: a case run as a convergence and cost study. system/studyDict names the entries to
// vary (any entry, by the paths mfDictionary uses: <file under the case>/<scoped key>), as named
// variants, a product of axes, and a resolution axis whose spacing sets the entries that follow
// from it. Each variant is a copy of the case in study/<variant>/ with its entries set, run side
// by side up to `jobs` at a time; a variant that finished has a marker and is not rerun, so a
// killed study resumes. The results (error norms and reference differences from each run's
// summary, CPU and wall time, steps, particles, peak memory) go to study/results.csv and
// study/results.md, with observed orders, Richardson extrapolation and gnuplot figures.
//
// Everything in studyDict is checked against the case before anything is written or run.
#include "StudyFit.hpp"
#include "core/Application.hpp"
#include "core/CaseLock.hpp"
#include "core/Dictionary.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <regex>
#include <set>
#include <sstream>
#include <thread>

#include <fcntl.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

namespace fs = std::filesystem;
using namespace mfdyn;

namespace {

constexpr const char* doneMarker = "mfStudy.done";
constexpr const char* settingsFile = "mfStudy.settings";  // the entries the variant was run with
constexpr const char* runnerLog = "log.mfStudy";

// ---------------------------------------------------------------- studyDict

struct Setting {
    std::string path;   // as written in studyDict: constant/sphProperties/kernel/type
    fs::path file;      // relative to the case: constant/sphProperties
    std::string key;    // scoped inside the file: kernel/type
    std::string value;  // the text mfDictionary -set writes
};

struct Variant {
    std::string name;    // its directory under study/
    std::string scheme;  // what it is apart from its resolution: one line per scheme in the plots
    std::optional<double> spacing;
    std::vector<Setting> settings;
};

enum class RunMode { automatic, allrun, application };

struct Study {
    RunMode mode = RunMode::automatic;
    int jobs = 1;
    std::string measure;  // "<functionObject>/<field>/<L1|L2|Linf>" or "<functionObject>/<quantity>"
    std::string application;
    std::vector<Variant> variants;
    // quantities { name "shell command"; }: a value of each finished run that no summary prints
    // (a twist angle from a probe's CSV), the last line the command writes in the variant's directory.
    std::vector<std::pair<std::string, std::string>> quantities;
};

std::string tokensText(const Entry& e) {
    if (e.isDict()) return "{\n" + e.dict->str(1) + "}";
    std::string s;
    for (const Token& t : e.tokens) s += (s.empty() ? "" : " ") + t.str();
    return s;
}

std::string joined(const std::vector<std::string>& words, const std::string& separator = " | ") {
    std::string s;
    for (const auto& w : words) s += (s.empty() ? "" : separator) + w;
    return s;
}

std::vector<std::string> splitPath(const std::string& path) {
    std::vector<std::string> parts;
    std::string part;
    for (char c : path + "/") {
        if (c != '/') {
            part += c;
        } else if (!part.empty()) {
            parts.push_back(part);
            part.clear();
        }
    }
    return parts;
}

// The dictionaries of a case that an entry path may start with (for the valid choices).
std::vector<std::string> caseDictionaries(const fs::path& root) {
    std::vector<std::string> files;
    for (const char* dir : {"system", "constant"}) {
        std::error_code ec;
        for (const auto& f : fs::directory_iterator(root / dir, ec))
            if (f.is_regular_file() && f.path().filename().string().find('.') == std::string::npos &&
                f.path().filename() != "studyDict")
                files.push_back(std::string(dir) + "/" + f.path().filename().string());
    }
    std::sort(files.begin(), files.end());
    return files;
}

// A studyDict entry path split into the case file it names and the scoped key inside it, checked:
// the file exists, the key exists in it, and the new value has the form of the old (a number for
// a number, a dictionary for a dictionary).
//
// `scaled` (a resolution's scale): a number may replace a list of numbers, every component set to
// it (a nodal lattice's `points (9 9 9)`), rounded to a whole number where they all are whole.
Setting resolveSetting(const fs::path& root, const std::string& path, const std::string& value,
                       const Entry* valueEntry, const SourceLocation& where, const std::string& scope,
                       bool scaled = false) {
    const auto parts = splitPath(path);
    std::size_t split = 0;
    fs::path file;
    for (std::size_t i = 1; i < parts.size(); ++i) {
        fs::path candidate;
        for (std::size_t j = 0; j < i; ++j) candidate /= parts[j];
        if (fs::is_regular_file(root / candidate)) {
            file = candidate;
            split = i;
            break;
        }
    }
    if (file.empty())
        throw InputError(where, scope,
                         "entry path '" + path + "' names no dictionary of the case " + root.string() +
                             "; valid choices: " + joined(caseDictionaries(root)) +
                             " (followed by /<entry>)");
    if (split == parts.size())
        throw InputError(where, scope,
                         "entry path '" + path + "' names the file " + file.string() +
                             " but no entry in it (write " + file.string() + "/<entry>)");
    const Dictionary dict = Dictionary::read(root / file);
    const Dictionary* within = &dict;
    const Entry* found = nullptr;
    std::string key;
    for (std::size_t i = split; i < parts.size(); ++i) {
        key += (key.empty() ? "" : "/") + parts[i];
        found = within ? within->peek(parts[i]) : nullptr;
        if (!found) {
            std::string choices = within ? joined(within->keys()) : std::string("(none: not a dictionary)");
            throw InputError(where, scope,
                             "entry path '" + path + "': " + file.string() + " has no entry '" + key +
                                 "'; valid choices at " +
                                 (within && !within->scope().empty() ? within->scope() : "its top level") +
                                 ": " + choices);
        }
        within = found->isDict() ? found->dict.get() : nullptr;
    }
    const bool newIsDict = valueEntry ? valueEntry->isDict() : (!value.empty() && value[0] == '{');
    if (found->isDict() != newIsDict)
        throw InputError(where, scope,
                         "'" + value + "' cannot replace " + path + ", which is " +
                             (found->isDict() ? "a dictionary { ... }" : "a value, not a dictionary"));
    if (scaled && found->tokens.size() == 1 && found->tokens[0].kind == Token::Kind::list &&
        !found->tokens[0].list.empty() &&
        std::all_of(found->tokens[0].list.begin(), found->tokens[0].list.end(),
                    [](const Token& t) { return t.isNumber(); })) {
        const auto& old = found->tokens[0].list;
        // The new components: one number for all, or a list of as many as the old has.
        std::vector<double> values;
        if (!value.empty() && value[0] == '(') {
            const Dictionary probe = Dictionary::parse("value " + value + ";", "studyDict");
            for (const Token& t : probe.entry("value").tokens[0].list) values.push_back(t.number());
            if (values.size() != old.size())
                throw InputError(where, scope,
                                 "the scale of " + path + " gives " + std::to_string(values.size()) +
                                     " components, and it has " + std::to_string(old.size()) + " (now " +
                                     tokensText(*found) + ")");
        } else {
            values.assign(old.size(), std::strtod(value.c_str(), nullptr));
        }
        std::string list = "(";
        for (std::size_t k = 0; k < old.size(); ++k) {
            double v = values[k];
            if (old[k].number() == std::floor(old[k].number())) v = std::round(v);  // a count stays one
            char text[40];
            std::snprintf(text, sizeof text, "%.10g", v);
            list += (k ? " " : "") + std::string(text);
        }
        return {path, file, key, list + ")"};
    }
    const bool oldIsNumber = found->tokens.size() == 1 && found->tokens[0].isNumber();
    if (oldIsNumber) {
        const Dictionary probe =
            Dictionary::parse("value " + value + ";", where.file ? *where.file : "studyDict");
        const Entry& parsed = probe.entry("value");
        if (parsed.tokens.size() != 1 || !parsed.tokens[0].isNumber())
            throw InputError(
                where, scope,
                "'" + value + "' is not a number, and " + path + " is one (now " + tokensText(*found) + ")");
    }
    return {path, file, key, value};
}

std::string safeName(const std::string& text) {
    std::string s;
    for (char c : text)
        s += (std::isalnum(static_cast<unsigned char>(c)) || c == '.' || c == '-' || c == '+') ? c : '_';
    return s;
}

std::string number(double v) {
    char s[40];
    std::snprintf(s, sizeof s, "%.10g", v);
    return s;
}

const std::vector<std::string> studyKeywords{"run",  "jobs",     "error",     "resolution",
                                             "axes", "variants", "quantities"};

Study readStudy(const fs::path& root, std::optional<int> jobsOption) {
    const fs::path studyFile = root / "system" / "studyDict";
    if (!fs::exists(studyFile)) throw InputError("no study dictionary " + studyFile.string());
    const Dictionary dict = Dictionary::read(studyFile);
    for (const auto& e : dict.entries())
        if (std::find(studyKeywords.begin(), studyKeywords.end(), e->key) == studyKeywords.end()) {
            const std::string guess = closestMatch(e->key, studyKeywords);
            throw InputError(e->where, "",
                             "unknown keyword '" + e->key + "'" +
                                 (guess.empty() ? "" : " (did you mean '" + guess + "'?)") +
                                 "; valid choices: " + joined(studyKeywords));
        }

    Study study;
    const std::string mode = dict.getOrDefault<std::string>("run", "auto");
    if (mode == "auto")
        study.mode = RunMode::automatic;
    else if (mode == "allrun")
        study.mode = RunMode::allrun;
    else if (mode == "application")
        study.mode = RunMode::application;
    else
        throw dict.error("run",
                         "'" + mode + "' is not a way to run; valid choices: auto | allrun | application");
    if (study.mode == RunMode::automatic)
        study.mode = fs::exists(root / "Allrun") ? RunMode::allrun : RunMode::application;
    if (study.mode == RunMode::allrun && !fs::exists(root / "Allrun"))
        throw dict.error("run", "run allrun, but the case has no Allrun; valid choices: auto | application");

    study.jobs = dict.getOrDefault<int>("jobs", 1);
    if (jobsOption) study.jobs = *jobsOption;
    if (study.jobs < 1)
        throw dict.error("jobs", "jobs must be at least 1, not " + std::to_string(study.jobs));

    if (const Entry* q = dict.findEntry("quantities")) {
        if (!q->isDict() || q->dict->size() == 0)
            throw InputError(q->where, "",
                             "quantities must be a dictionary { <name> \"<shell command>\"; ... } naming at "
                             "least one");
        for (const auto& e : q->dict->entries()) {
            if (e->isDict() || e->tokens.size() != 1 || e->tokens[0].kind != Token::Kind::string)
                throw InputError(e->where, "quantities",
                                 "quantity '" + e->key +
                                     "' must be one quoted shell command, run in each finished variant's "
                                     "directory, whose last line of output is the value");
            study.quantities.emplace_back(e->key, e->tokens[0].text);
        }
    }

    study.measure = dict.getOrDefault<std::string>("error", "");
    if (!study.measure.empty()) {
        const auto parts = splitPath(study.measure);
        const bool norm = parts.size() == 3 && (parts[2] == "L1" || parts[2] == "L2" || parts[2] == "Linf");
        if (!norm && parts.size() != 2)
            throw dict.error("error",
                             "'" + study.measure +
                                 "' is not a measure; valid forms: <functionObject>/<field>/<L1 | L2 | Linf> "
                                 "(an error norm of the summary) or <functionObject>/<quantity> (a value "
                                 "the summary compares with its exact one)");
    }

    const fs::path controlDict = root / "system" / "controlDict";
    if (!fs::exists(controlDict))
        throw InputError("the case " + root.string() + " has no system/controlDict");
    const Dictionary control = Dictionary::read(controlDict);
    if (auto app = control.getOptional<std::string>("application")) study.application = *app;
    if (study.application.empty())
        throw InputError(control.where(), "",
                         "controlDict names no application: mfStudy runs it and reads log.<application>");
    // The measure's function object must be one the case runs (its fields are known only after a run).
    if (!study.measure.empty()) {
        const std::string object = splitPath(study.measure).front();
        std::vector<std::string> objects;
        if (const Dictionary* functions = control.findDict("functions")) objects = functions->keys();
        if (std::find(objects.begin(), objects.end(), object) == objects.end())
            throw dict.error(
                "error", "'" + object + "' is not a function object of system/controlDict; valid choices: " +
                             (objects.empty() ? std::string("(none: controlDict has no functions)")
                                              : joined(objects)));
    }

    // The axes that are not resolution, as (label, settings) choices; their product times the levels.
    struct Choice {
        std::string label;
        std::vector<Setting> settings;
    };
    std::vector<std::vector<Choice>> factors;

    if (const Entry* v = dict.findEntry("variants")) {
        if (!v->isDict())
            throw InputError(v->where, "",
                             "variants must be a dictionary { name { <entry path> value; ... } ... }");
        std::vector<Choice> choices;
        for (const auto& variant : v->dict->entries()) {
            if (!variant->isDict())
                throw InputError(
                    variant->where, "variants",
                    "variant '" + variant->key + "' must be a dictionary { <entry path> value; ... }");
            if (variant->dict->size() == 0)
                throw InputError(variant->where, "variants/" + variant->key,
                                 "empty variant: it sets no entry");
            Choice choice{variant->key, {}};
            for (const auto& set : variant->dict->entries())
                choice.settings.push_back(resolveSetting(root, set->key, tokensText(*set), set.get(),
                                                         set->where, "variants/" + variant->key));
            choices.push_back(std::move(choice));
        }
        if (choices.empty()) throw InputError(v->where, "", "empty list of variants: name at least one");
        factors.push_back(std::move(choices));
    }

    if (const Entry* a = dict.findEntry("axes")) {
        if (!a->isDict())
            throw InputError(a->where, "",
                             "axes must be a dictionary { name { entry <path>; values (...); } }");
        if (a->dict->size() == 0) throw InputError(a->where, "", "empty axes: name at least one axis");
        for (const auto& axis : a->dict->entries()) {
            const std::string scope = "axes/" + axis->key;
            if (!axis->isDict())
                throw InputError(axis->where, "axes",
                                 "axis '" + axis->key + "' must be { entry <path>; values (...); }");
            const Dictionary& ad = *axis->dict;
            for (const auto& k : ad.keys())
                if (k != "entry" && k != "values")
                    throw ad.error(k, "unknown keyword '" + k + "'; valid choices: entry | values");
            const std::string path = ad.get<std::string>("entry");
            const Entry& values = ad.entry("values");
            if (values.tokens.size() != 1 || values.tokens[0].kind != Token::Kind::list)
                throw InputError(values.where, scope, "values must be a list ( v1 v2 ... )");
            const auto& list = values.tokens[0].list;
            if (list.empty())
                throw InputError(values.where, scope, "empty list of values: give at least one");
            std::vector<Choice> choices;
            for (const Token& t : list) {
                if (t.kind == Token::Kind::dictionary) {
                    const std::string text = t.str();
                    choices.push_back({axis->key + "-" + std::to_string(choices.size()),
                                       {resolveSetting(root, path, text, nullptr,
                                                       t.where.known() ? t.where : values.where, scope)}});
                } else {
                    const std::string text = t.str();
                    choices.push_back({axis->key + "-" + t.str(),
                                       {resolveSetting(root, path, text, nullptr,
                                                       t.where.known() ? t.where : values.where, scope)}});
                }
            }
            factors.push_back(std::move(choices));
        }
    }

    struct Rule {
        double factor = 1, power = 1, offset = 0;
        double at(double h) const { return factor * std::pow(h, power) + offset; }
    };
    struct Scaled {
        std::string path;
        Rule rule;
        const Entry* entry = nullptr;
        std::vector<Rule> components;  // a list entry set component by component (else empty)
        std::string at(double h) const {
            if (components.empty()) return number(rule.at(h));
            std::string list = "(";
            for (const Rule& c : components) list += (list.size() > 1 ? " " : "") + number(c.at(h));
            return list + ")";
        }
    };
    std::vector<double> spacings;
    std::vector<Scaled> scaled;
    if (const Entry* r = dict.findEntry("resolution")) {
        if (!r->isDict())
            throw InputError(r->where, "",
                             "resolution must be { spacing (h1 h2 ...); scale { <entry path> factor; } }");
        const Dictionary& rd = *r->dict;
        for (const auto& k : rd.keys())
            if (k != "spacing" && k != "scale")
                throw rd.error(k, "unknown keyword '" + k + "'; valid choices: spacing | scale");
        spacings = rd.get<std::vector<double>>("spacing");
        if (spacings.empty()) throw rd.error("spacing", "empty list of spacings: give at least one");
        for (double h : spacings)
            if (!(h > 0) || !std::isfinite(h))
                throw rd.error("spacing", "spacing " + number(h) + " is not positive");
        const Dictionary& scale = rd.subDict("scale");
        if (scale.size() == 0)
            throw rd.error("scale", "no entries follow the spacing: name at least one <entry path> factor;");
        for (const auto& e : scale.entries()) {
            Scaled s{e->key, {}, e.get(), {}};
            // factor | (factor power) | (factor power offset): one rule.
            const auto ruleOf = [](const Token& t) -> std::optional<Rule> {
                if (t.isNumber()) return Rule{t.number(), 1, 0};
                if (t.kind != Token::Kind::list || t.list.size() < 2 || t.list.size() > 3 ||
                    !std::all_of(t.list.begin(), t.list.end(), [](const Token& c) { return c.isNumber(); }))
                    return std::nullopt;
                return Rule{t.list[0].number(), t.list[1].number(),
                            t.list.size() == 3 ? t.list[2].number() : 0};
            };
            const bool componentwise =
                e->tokens.size() == 1 && e->tokens[0].kind == Token::Kind::list &&
                std::any_of(e->tokens[0].list.begin(), e->tokens[0].list.end(),
                            [](const Token& c) { return c.kind == Token::Kind::list; });
            bool valid = e->tokens.size() == 1;
            if (valid && componentwise) {
                // ((10 -1 1) 3 3): each component its rule, a plain number a constant.
                for (const Token& c : e->tokens[0].list) {
                    const auto r = c.isNumber() ? std::optional<Rule>(Rule{0, 0, c.number()}) : ruleOf(c);
                    if (r)
                        s.components.push_back(*r);
                    else
                        valid = false;
                }
            } else if (valid) {
                const auto r = ruleOf(e->tokens[0]);
                if (r)
                    s.rule = *r;
                else
                    valid = false;
            }
            if (!valid) {
                throw InputError(e->where, "resolution/scale",
                                 "'" + tokensText(*e) +
                                     "' is not a scale; valid forms: factor (value = factor h), "
                                     "(factor power) (value = factor h^power) or (factor power offset) "
                                     "(value = factor h^power + offset: (1 -1 1) is the 1/h + 1 nodes of "
                                     "a nodal lattice on a unit length); on a list entry, a list of "
                                     "those and constants, one per component: ((10 -1 1) 3 3)");
            }
            // Checked once with the first spacing; every level sets the same entries.
            resolveSetting(root, s.path, s.at(spacings[0]), nullptr, e->where, "resolution/scale", true);
            scaled.push_back(s);
        }
    }

    if (factors.empty() && spacings.empty())
        throw InputError(dict.where(), "", "studyDict varies nothing; give variants, axes or resolution");

    // The product: every combination of the factors, each at every resolution level.
    std::vector<Choice> combinations{{"", {}}};
    for (const auto& factor : factors) {
        std::vector<Choice> next;
        for (const auto& base : combinations)
            for (const auto& choice : factor) {
                Choice c{base.label.empty() ? choice.label : base.label + "_" + choice.label, base.settings};
                c.settings.insert(c.settings.end(), choice.settings.begin(), choice.settings.end());
                next.push_back(std::move(c));
            }
        combinations = std::move(next);
    }
    std::set<std::string> names;
    for (const auto& c : combinations) {
        const auto addVariant = [&](std::optional<double> h) {
            Variant v;
            v.scheme = c.label.empty() ? "base" : c.label;
            v.spacing = h;
            v.settings = c.settings;
            std::string name = c.label;
            if (h) {
                name += (name.empty() ? "" : "_") + std::string("h") + number(*h);
                for (const auto& s : scaled) v.settings.push_back({s.path, {}, {}, s.at(*h)});
            }
            v.name = safeName(name);
            if (!names.insert(v.name).second)
                throw InputError(
                    dict.where(), "",
                    "two variants are both named '" + v.name + "': give them distinct names or values");
            study.variants.push_back(std::move(v));
        };
        if (spacings.empty())
            addVariant(std::nullopt);
        else
            for (double h : spacings) addVariant(h);
    }
    // The scaled settings were checked above; give them their file and key.
    for (auto& v : study.variants)
        for (auto& s : v.settings)
            if (s.file.empty())
                s = resolveSetting(root, s.path, s.value, nullptr, {}, "resolution/scale", true);
    return study;
}

// ---------------------------------------------------------------- files

void writeAtomically(const fs::path& path, const std::string& text) {
    const fs::path tmp = path.string() + ".tmp";
    {
        std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
        out << text;
        out.flush();
        if (!out) throw Error("cannot write '" + tmp.string() + "'");
    }
    fs::rename(tmp, path);
}

std::string readText(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

std::string settingsText(const Variant& v) {
    std::string text;
    for (const auto& s : v.settings) text += s.path + " " + s.value + "\n";
    return text;
}

bool isTimeName(const std::string& name) {
    if (name.empty()) return false;
    char* end = nullptr;
    std::strtod(name.c_str(), &end);
    return end && *end == '\0';
}

// The case's inputs: its top-level entries without its results, the study itself, or initial
// conditions that particleGen writes again.
std::vector<fs::path> caseInputs(const fs::path& root) {
    const bool generated = fs::exists(root / "system" / "particleGenDict");
    std::vector<fs::path> inputs;
    for (const auto& e : fs::directory_iterator(root)) {
        const std::string name = e.path().filename().string();
        if (name == "study" || name == "postProcessing" || name == "particles.pvd" ||
            name.rfind("log.", 0) == 0 || name.rfind("abandoned.", 0) == 0 ||
            name.find(".tmp") != std::string::npos || e.path().extension() == ".png" ||
            (isTimeName(name) && (name != "0" || generated)) || name.rfind(".mfdyn", 0) == 0)
            continue;
        inputs.push_back(e.path());
    }
    std::sort(inputs.begin(), inputs.end());
    return inputs;
}

void copyInputs(const fs::path& root, const fs::path& to) {
    fs::create_directories(to);
    for (const auto& input : caseInputs(root))
        fs::copy(input, to / input.filename(), fs::copy_options::recursive | fs::copy_options::copy_symlinks);
}

// A fingerprint of every file the variants copy (FNV-1a over each one's path in the case and its
// bytes, in path order), studyDict left out: its entries are compared one by one (settingsFile),
// and a level added to it must not rerun the others. A finished variant whose marker holds
// another fingerprint was run from another case: a changed endTime, material or mesh.
std::string inputsFingerprint(const fs::path& root) {
    std::uint64_t hash = 1469598103934665603ull;
    const auto mix = [&](const char* data, std::size_t n) {
        for (std::size_t i = 0; i < n; ++i) {
            hash ^= static_cast<unsigned char>(data[i]);
            hash *= 1099511628211ull;
        }
    };
    std::vector<fs::path> files;
    for (const auto& input : caseInputs(root)) {
        std::error_code ec;
        if (fs::is_directory(input, ec)) {
            for (auto it = fs::recursive_directory_iterator(input, ec); !ec && it != fs::end(it);
                 it.increment(ec))
                if (it->is_regular_file(ec)) files.push_back(it->path());
        } else {
            files.push_back(input);
        }
    }
    std::sort(files.begin(), files.end());
    const fs::path studyDict = root / "system" / "studyDict";
    for (const auto& file : files) {
        if (file == studyDict) continue;
        const std::string name = file.lexically_relative(root).generic_string();
        mix(name.c_str(), name.size() + 1);
        std::ifstream in(file, std::ios::binary);
        char buffer[65536];
        while (in.read(buffer, sizeof buffer) || in.gcount() > 0) mix(buffer, std::size_t(in.gcount()));
        mix("", 1);
    }
    char text[20];
    std::snprintf(text, sizeof text, "%016llx", static_cast<unsigned long long>(hash));
    return text;
}

// A toolkit program run to completion with its output discarded (no shell: values need no quoting).
int runTool(const fs::path& program, const std::vector<std::string>& arguments) {
    std::vector<std::string> words{program.string()};
    words.insert(words.end(), arguments.begin(), arguments.end());
    std::vector<char*> argv;
    for (auto& w : words) argv.push_back(w.data());
    argv.push_back(nullptr);
    const pid_t pid = fork();
    if (pid < 0) return -1;
    if (pid == 0) {
        const int null = open("/dev/null", O_WRONLY);
        if (null >= 0) dup2(null, 1);
        execv(argv[0], argv.data());
        _exit(127);
    }
    int status = 0;
    while (waitpid(pid, &status, 0) < 0)
        if (errno != EINTR) return -1;
    return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

fs::path executableDirectory() {
    std::error_code ec;
    const fs::path self = fs::read_symlink("/proc/self/exe", ec);
    return ec ? fs::path() : self.parent_path();
}

// ---------------------------------------------------------------- running

volatile std::sig_atomic_t stopSignal = 0;
extern "C" void requestStop(int signal) {
    stopSignal = signal;
}

struct Running {
    std::size_t variant = 0;
    pid_t pid = -1;
    std::chrono::steady_clock::time_point start;
};

struct Outcome {
    bool finished = false;  // a done marker
    bool ran = false;       // run by this invocation (not resumed)
    double cpuSeconds = 0, wallSeconds = 0, maxRssBytes = 0;
    std::string diagnosis;
};

// The first error line of the variant's logs: the solver's, particleGen's, then the runner's.
std::string diagnose(const fs::path& dir, const std::string& application, int status) {
    std::vector<fs::path> logs{dir / ("log." + application), dir / "log.particleGen"};
    std::error_code ec;
    for (const auto& e : fs::directory_iterator(dir, ec))
        if (e.path().filename().string().rfind("log.", 0) == 0 &&
            std::find(logs.begin(), logs.end(), e.path()) == logs.end())
            logs.push_back(e.path());
    for (const auto& log : logs) {
        std::ifstream in(log);
        std::string line;
        while (std::getline(in, line))
            // "Error: ..." and "Error (internal): ..." (Application.cpp), not the summary's "Error norms".
            if (line.rfind("Error:", 0) == 0 || line.rfind("Error (", 0) == 0 ||
                line.find("FATAL") != std::string::npos)
                return line;
    }
    // No error line: the runner's last words (a shell's "command not found", an Allrun's message).
    std::string last;
    {
        std::ifstream in(dir / runnerLog);
        for (std::string line; std::getline(in, line);)
            if (!line.empty()) last = line;
    }
    return (WIFSIGNALED(status) ? "killed by signal " + std::to_string(WTERMSIG(status))
                                : "exit status " + std::to_string(WEXITSTATUS(status))) +
           (last.empty() ? " without an error line; see " + (dir / runnerLog).string() : ": " + last);
}

pid_t launch(const fs::path& dir, const Study& study, const fs::path& binDir, int threadsPerJob) {
    std::string script;
    if (study.mode == RunMode::allrun) {
        script = "exec bash ./Allrun";
    } else {
        script =
            "set -e\n"
            "if [ -f system/particleGenDict ]; then particleGen -case . > log.particleGen 2>&1; fi\n"
            "exec '" +
            study.application + "' -case . > 'log." + study.application + "' 2>&1\n";
    }
    const pid_t pid = fork();
    if (pid < 0) throw Error(std::string("cannot start a variant: ") + std::strerror(errno));
    if (pid > 0) return pid;
    // The child: its own process group, so that a stop reaches the solver under the shell.
    setpgid(0, 0);
    if (chdir(dir.c_str()) != 0) _exit(126);
    const int out = open(runnerLog, O_WRONLY | O_CREAT | O_TRUNC, 0644);
    if (out >= 0) {
        dup2(out, 1);
        dup2(out, 2);
        close(out);
    }
    if (!binDir.empty()) {
        const char* path = std::getenv("PATH");
        setenv("PATH", (binDir.string() + ":" + (path ? path : "/usr/bin:/bin")).c_str(), 1);
        // An Allrun finds RunFunctions and the build through these when the copy sits outside the tree.
        const fs::path checkout = binDir.parent_path().parent_path();
        if (!std::getenv("MFDYN_DIR") && fs::exists(checkout / "bin" / "tools" / "RunFunctions"))
            setenv("MFDYN_DIR", checkout.c_str(), 1);
        if (!std::getenv("MFDYN_BUILD")) setenv("MFDYN_BUILD", binDir.parent_path().c_str(), 1);
    }
    if (threadsPerJob > 0) setenv("OMP_NUM_THREADS", std::to_string(threadsPerJob).c_str(), 1);
    execl("/bin/bash", "bash", "-c", script.c_str(), static_cast<char*>(nullptr));
    _exit(127);
}

// The done marker: "key value" lines (cpuSeconds, wallSeconds, maxRssBytes, baseInputs).
std::map<std::string, std::string> readMarker(const fs::path& file) {
    std::map<std::string, std::string> values;
    std::ifstream in(file);
    std::string key, value;
    while (in >> key >> value) values[key] = value;
    return values;
}

double markerNumber(const std::map<std::string, std::string>& marker, const std::string& key) {
    const auto it = marker.find(key);
    return it == marker.end() ? 0.0 : std::strtod(it->second.c_str(), nullptr);
}

// Runs the variants without a done marker, `jobs` at a time. Returns 0, or 128 + the signal
// that stopped it (the running variants are stopped too and rerun next time).
int runVariants(const fs::path& studyDir, const Study& study, std::vector<Outcome>& outcomes) {
    const fs::path binDir = executableDirectory();
    // Side by side runs share the cores: each gets its share unless the user chose a count.
    const int cores = int(std::max(1u, std::thread::hardware_concurrency()));
    const int threadsPerJob = std::getenv("OMP_NUM_THREADS") ? 0 : std::max(1, cores / study.jobs);

    struct sigaction action {};
    action.sa_handler = requestStop;
    sigemptyset(&action.sa_mask);
    action.sa_flags = 0;  // no SA_RESTART: wait4 returns so that a stop is seen at once
    sigaction(SIGINT, &action, nullptr);
    sigaction(SIGTERM, &action, nullptr);

    const std::string fingerprint = inputsFingerprint(studyDir.parent_path());
    std::vector<std::size_t> pending;
    for (std::size_t i = 0; i < study.variants.size(); ++i) {
        const fs::path dir = studyDir / study.variants[i].name;
        // A finished variant whose entries studyDict has since changed is stale: it runs again.
        const bool same =
            fs::exists(dir / settingsFile) && readText(dir / settingsFile) == settingsText(study.variants[i]);
        const bool done = fs::exists(dir / doneMarker);
        const auto m = done ? readMarker(dir / doneMarker) : std::map<std::string, std::string>{};
        // So is one run from other inputs of the base case (a marker without a fingerprint too:
        // nothing says what it was run from).
        const bool sameInputs = m.count("baseInputs") && m.at("baseInputs") == fingerprint;
        if (done && !same)
            std::cout << "    " << study.variants[i].name
                      << ": its entries changed in studyDict since it ran: rerun\n";
        else if (done && !sameInputs)
            std::cout << "    " << study.variants[i].name
                      << ": the base case's inputs (files the variants copy) changed since it ran: rerun\n";
        if (done && same && sameInputs) {
            outcomes[i].finished = true;
            outcomes[i].cpuSeconds = markerNumber(m, "cpuSeconds");
            outcomes[i].wallSeconds = markerNumber(m, "wallSeconds");
            outcomes[i].maxRssBytes = markerNumber(m, "maxRssBytes");
            std::cout << "    " << study.variants[i].name << ": finished before, not rerun\n";
        } else {
            pending.push_back(i);
        }
    }
    std::reverse(pending.begin(), pending.end());
    std::vector<Running> running;
    while (!stopSignal && (!pending.empty() || !running.empty())) {
        while (!stopSignal && !pending.empty() && int(running.size()) < study.jobs) {
            const std::size_t i = pending.back();
            pending.pop_back();
            const Variant& v = study.variants[i];
            const fs::path dir = studyDir / v.name;
            // A variant without a marker was stopped or failed: it starts again from the case.
            fs::remove_all(dir);
            const fs::path partial = studyDir / (v.name + ".partial");
            fs::remove_all(partial);
            copyInputs(studyDir.parent_path(), partial);
            for (const auto& s : v.settings)
                if (runTool(binDir / "mfDictionary",
                            {(partial / s.file).string(), "-entry", s.key, "-set", s.value}) != 0)
                    throw Error("cannot set " + s.path + " to " + s.value + " in " + partial.string());
            writeAtomically(partial / settingsFile, settingsText(v));
            fs::rename(partial, dir);
            std::cout << "    " << v.name << ": running" << std::endl;
            running.push_back(
                {i, launch(dir, study, binDir, threadsPerJob), std::chrono::steady_clock::now()});
        }
        if (running.empty()) break;
        int status = 0;
        struct rusage usage {};
        const pid_t pid = wait4(-1, &status, 0, &usage);
        if (pid < 0) {
            if (errno == EINTR) continue;
            throw Error(std::string("waiting for a variant: ") + std::strerror(errno));
        }
        const auto it =
            std::find_if(running.begin(), running.end(), [&](const Running& r) { return r.pid == pid; });
        if (it == running.end()) continue;
        const Variant& v = study.variants[it->variant];
        Outcome& o = outcomes[it->variant];
        const fs::path dir = studyDir / v.name;
        o.ran = true;
        o.wallSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - it->start).count();
        // The kernel's accounting of the variant's whole process tree: shell, particleGen, solver.
        o.cpuSeconds = double(usage.ru_utime.tv_sec) + 1e-6 * double(usage.ru_utime.tv_usec) +
                       double(usage.ru_stime.tv_sec) + 1e-6 * double(usage.ru_stime.tv_usec);
        o.maxRssBytes = 1024.0 * double(usage.ru_maxrss);
        const bool ok =
            WIFEXITED(status) && WEXITSTATUS(status) == 0 && fs::exists(dir / ("log." + study.application));
        if (ok && !stopSignal) {
            std::ostringstream marker;
            marker << "cpuSeconds " << number(o.cpuSeconds) << "\nwallSeconds " << number(o.wallSeconds)
                   << "\nmaxRssBytes " << number(o.maxRssBytes) << "\nbaseInputs " << fingerprint << "\n";
            writeAtomically(dir / doneMarker, marker.str());
            o.finished = true;
            std::cout << "    " << v.name << ": finished (" << number(o.cpuSeconds) << " s CPU)" << std::endl;
        } else if (!stopSignal) {
            o.diagnosis = diagnose(dir, study.application, status);
            std::cout << "    " << v.name << ": FAILED: " << o.diagnosis << std::endl;
        }
        running.erase(it);
    }
    if (!stopSignal) return 0;
    for (const auto& r : running) kill(-r.pid, SIGTERM);
    for (const auto& r : running) {
        int status = 0;
        while (waitpid(r.pid, &status, 0) < 0 && errno == EINTR) {
        }
    }
    std::size_t done = 0;
    for (const auto& o : outcomes) done += o.finished;
    std::cout << "Stopped by signal " << stopSignal << ": " << done << " of " << outcomes.size()
              << " variants finished; run mfStudy again to resume (finished variants are not rerun)"
              << std::endl;
    return 128 + stopSignal;
}

// ---------------------------------------------------------------- results

struct Reference {
    double value = 0, exact = 0;
};

struct Result {
    std::map<std::string, double> norms;          // "riemann/density/L1"
    std::map<std::string, double> exactNorms;     // the same norms of the exact field (relative error)
    std::map<std::string, Reference> references;  // "riemann/starPressure"
    double wallSeconds = NAN, steps = NAN, particles = NAN, peakMemoryBytes = NAN;
};

std::vector<std::string> csvFields(const std::string& line) {
    std::vector<std::string> fields;
    std::string f;
    for (char c : line + ",") {
        if (c == ',') {
            fields.push_back(f);
            f.clear();
        } else if (c != '\r') {
            f += c;
        }
    }
    return fields;
}

double toNumber(const std::string& text) {
    char* end = nullptr;
    const double v = std::strtod(text.c_str(), &end);
    return end != text.c_str() ? v : NAN;
}

// A run's results: its runSummary.csv (the summary's error norms at full precision, wall time,
// steps, particles) and its log: peak memory, and the summary's error lines (SolverRun),
//     error <object>/<field>/<L1|L2|Linf>  <norm> (exact <norm of the exact field>, relative ..) ...
//     error <object>/<quantity>  <value> (exact <x>, relative <r>) at CPU <s> s, step <n>, t = <t>
// A log without them (a solver built before they were printed) gives its values through the
// Diagnostics lines that compare one with its exact one, "name value (exact reference, ...)".
Result collect(const fs::path& dir, const std::string& application, std::vector<std::string>& normOrder,
               std::vector<std::string>& referenceOrder) {
    Result r;
    const auto noteOrder = [](std::vector<std::string>& order, const std::string& key) {
        if (std::find(order.begin(), order.end(), key) == order.end()) order.push_back(key);
    };
    std::error_code ec;
    std::vector<fs::path> summaries;
    for (const auto& e : fs::directory_iterator(dir / "postProcessing" / "runSummary", ec))
        if (fs::exists(e.path() / "runSummary.csv")) summaries.push_back(e.path() / "runSummary.csv");
    // After restarts, the run of the latest start holds the final summary.
    std::sort(summaries.begin(), summaries.end(), [](const fs::path& a, const fs::path& b) {
        return toNumber(a.parent_path().filename().string()) < toNumber(b.parent_path().filename().string());
    });
    if (!summaries.empty()) {
        std::ifstream in(summaries.back());
        std::string line;
        std::getline(in, line);
        const auto header = csvFields(line);
        const auto column = [&](const std::string& name) {
            return std::size_t(std::find(header.begin(), header.end(), name) - header.begin());
        };
        while (std::getline(in, line)) {
            const auto f = csvFields(line);
            if (f.size() != header.size()) continue;
            r.wallSeconds = toNumber(f[column("wallTime")]);
            r.steps = toNumber(f[column("steps")]);
            r.particles = toNumber(f[column("particles")]);
            const std::string field = f[column("field")];
            if (field == "none") continue;
            for (const char* norm : {"L1", "L2", "Linf"}) {
                const std::string key = field + "/" + norm;
                r.norms[key] = toNumber(f[column(norm)]);
                noteOrder(normOrder, key);
            }
        }
    }
    std::ifstream log(dir / ("log." + application));
    std::string line;
    bool diagnostics = false, errorLines = false;
    std::map<std::string, Reference> fromDiagnostics;
    std::vector<std::string> diagnosticsOrder;
    static const std::regex errorLine(
        R"(^    error (\S+)  (\S+) \(exact (\S+), relative (\S+)\) at CPU (\S+) s, step (\S+), t = (\S+)$)");
    static const std::regex compared(
        R"((?:^|[,:;]\s*)([A-Za-z][A-Za-z ]*?)\s*=?\s+(-?[0-9][0-9.]*(?:[eE][-+]?[0-9]+)?)\s*[A-Za-z]*\s*\(exact\s+(-?[0-9][0-9.]*(?:[eE][-+]?[0-9]+)?))");
    while (std::getline(log, line)) {
        if (line.rfind("    peak memory", 0) == 0) {
            std::istringstream s(line.substr(15));
            double v = 0;
            std::string unit;
            s >> v >> unit;
            const std::map<std::string, double> scale{
                {"B", 1}, {"KiB", 1024}, {"MiB", 1048576}, {"GiB", 1073741824.0}};
            if (scale.count(unit)) r.peakMemoryBytes = v * scale.at(unit);
        }
        if (std::smatch m; line.rfind("    error ", 0) == 0 && std::regex_match(line, m, errorLine)) {
            errorLines = true;
            const std::string key = m[1].str();
            const auto parts = splitPath(key);
            const bool norm =
                parts.size() == 3 && (parts[2] == "L1" || parts[2] == "L2" || parts[2] == "Linf");
            if (norm) {
                r.exactNorms[key] = toNumber(m[3].str());
                // The CSV's norm at full precision is kept; a log line fills in one it lacks.
                if (!r.norms.count(key)) r.norms[key] = toNumber(m[2].str()), noteOrder(normOrder, key);
            } else {
                r.references[key] = {toNumber(m[2].str()), toNumber(m[3].str())};
                noteOrder(referenceOrder, key);
            }
            continue;
        }
        if (line.rfind("Diagnostics:", 0) == 0) {
            diagnostics = true;
            continue;
        }
        if (diagnostics && line.rfind("    ", 0) != 0) diagnostics = false;
        if (!diagnostics) continue;
        const auto colon = line.find(": ");
        if (colon == std::string::npos) continue;
        std::string source = line.substr(4, colon - 4);
        const std::string text = line.substr(colon + 2);
        for (std::sregex_iterator m(text.begin(), text.end(), compared), end; m != end; ++m) {
            const std::string key = source + "/" + (*m)[1].str();
            fromDiagnostics[key] = {toNumber((*m)[2].str()), toNumber((*m)[3].str())};
            diagnosticsOrder.push_back(key);
        }
    }
    // The Diagnostics' "(exact ...)" values only where the log has no error lines: they would
    // repeat the same values under other names ("star pressure" beside "starPressure").
    if (!errorLines)
        for (const auto& key : diagnosticsOrder) {
            r.references[key] = fromDiagnostics.at(key);
            noteOrder(referenceOrder, key);
        }
    return r;
}

double measureOf(const Result& r, const std::string& measure) {
    if (auto n = r.norms.find(measure); n != r.norms.end()) return n->second;
    if (auto q = r.references.find(measure); q != r.references.end())
        return q->second.exact != 0 ? std::abs(q->second.value - q->second.exact) / std::abs(q->second.exact)
                                    : std::abs(q->second.value);
    return NAN;
}

// The measure relative to the size of the solution, what the targets 10%, 1%, 0.1% are on: a
// norm over the same norm of the exact field (NaN where the run did not give it), a value's
// |value - exact|/|exact|.
double relativeOf(const Result& r, const std::string& measure) {
    if (auto n = r.norms.find(measure); n != r.norms.end()) {
        const auto e = r.exactNorms.find(measure);
        return e != r.exactNorms.end() && e->second > 0 ? n->second / e->second : NAN;
    }
    if (auto q = r.references.find(measure); q != r.references.end())
        return q->second.exact != 0 ? std::abs(q->second.value - q->second.exact) / std::abs(q->second.exact)
                                    : NAN;
    return NAN;
}

std::string csvQuoted(const std::string& text) {
    std::string s = "\"";
    for (char c : text) s += c == '"' ? std::string("\"\"") : std::string(1, c);
    return s + "\"";
}

std::string shortNumber(double v) {
    if (!std::isfinite(v)) return "";
    char s[32];
    std::snprintf(s, sizeof s, "%.4g", v);
    return s;
}

// A table cell: a '|' in a diagnosis would split it.
std::string markdownCell(const std::string& text) {
    std::string s;
    for (char c : text) s += c == '|' ? std::string("\\|") : std::string(1, c);
    return s;
}

struct SchemeLine {
    std::string scheme;
    std::vector<std::size_t> runs;  // finished variants, finest last
    std::optional<double> orderH, orderCpu;
    std::optional<study::Richardson> extrapolation;
    std::vector<std::optional<double>> cpuToTarget;
};

// Relative errors (relativeOf) at which each scheme's CPU time is reported.
const std::vector<double> targets{1e-1, 1e-2, 1e-3};

std::string targetName(double target) {
    char s[16];
    std::snprintf(s, sizeof s, "%g%%", 100 * target);
    return s;
}

std::string gnuplotText(const std::string& text) {
    std::string s;
    for (char c : text) s += (c == '\'' || c == '"' || c == '_') ? ' ' : c;
    return s;
}

// Two PNG figures by gnuplot: the measure against CPU time (log-log, a line per scheme, its fitted
// order, the Pareto front) and against the spacing. Returns what happened, for the log.
std::string plot(const fs::path& studyDir, const std::string& measure, const std::vector<SchemeLine>& lines,
                 const std::vector<double>& h, const std::vector<double>& cpu,
                 const std::vector<double>& error, const std::vector<std::size_t>& front) {
    if (std::system("command -v gnuplot > /dev/null 2>&1") != 0)
        return "gnuplot not found: plots skipped (results.csv and results.md are written)";
    std::ostringstream data;
    std::vector<std::string> titles, resolutionTitles;
    std::vector<double> limits;  // Richardson's value at h -> 0 per plotted line
    for (const auto& line : lines) {
        std::size_t points = 0;
        for (std::size_t i : line.runs)
            if (error[i] > 0 && cpu[i] > 0) {
                data << (std::isfinite(h[i]) ? h[i] : 1.0) << " " << cpu[i] << " " << error[i] << "\n";
                ++points;
            }
        if (!points) continue;
        data << "\n\n";
        std::string title = gnuplotText(line.scheme);
        if (line.orderCpu) title += ", order in CPU " + shortNumber(-*line.orderCpu);
        if (line.orderH) title += ", order in h " + shortNumber(*line.orderH);
        titles.push_back(title);
        std::string byH = gnuplotText(line.scheme);
        if (line.orderH) byH += ", order in h " + shortNumber(*line.orderH);
        if (line.extrapolation)
            byH += ", Richardson order " + shortNumber(line.extrapolation->order) + ", extrapolated " +
                   shortNumber(line.extrapolation->extrapolated);
        resolutionTitles.push_back(byH);
        limits.push_back(line.extrapolation ? line.extrapolation->extrapolated : NAN);
    }
    if (titles.empty())
        return measure.empty() ? "no finished run reported an error norm: plots skipped"
                               : "no finished run with a positive " + measure + ": plots skipped";
    for (std::size_t i : front) data << cpu[i] << " " << error[i] << "\n";
    writeAtomically(studyDir / "plot.dat", data.str());
    const bool haveH = std::any_of(h.begin(), h.end(), [](double v) { return std::isfinite(v); });
    std::ostringstream script;
    script << "set terminal pngcairo size 1100,750\nset logscale xy\nset grid\nset key outside below "
              "vertical maxcols 1 font ',10'\n"
           << "set ylabel '" << gnuplotText(measure) << "'\n";
    script << "set output 'errorVsCpu.png.tmp'\nset title 'error against CPU time'\nset xlabel 'CPU time "
              "(s)'\nplot ";
    for (std::size_t k = 0; k < titles.size(); ++k)
        script << "'plot.dat' index " << k << " using 2:3 with linespoints lw 2 pt 7 title '" << titles[k]
               << "', ";
    script << "'plot.dat' index " << titles.size()
           << " using 1:2 with points pt 6 ps 3 lc rgb 'black' title 'Pareto front'\n";
    if (haveH) {
        script << "set output 'errorVsResolution.png.tmp'\nset title 'error against spacing'\nset xlabel "
                  "'spacing h'\nplot ";
        for (std::size_t k = 0; k < titles.size(); ++k)
            script << (k ? ", " : "") << "'plot.dat' index " << k
                   << " using 1:3 with linespoints lw 2 pt 7 lc " << k + 1 << " title '"
                   << resolutionTitles[k] << "'";
        // The extrapolated value as a dashed level where the log axis can show it.
        for (std::size_t k = 0; k < limits.size(); ++k)
            if (limits[k] > 0)
                script << ", " << number(limits[k]) << " with lines dt 2 lc " << k + 1 << " notitle";
        script << "\n";
    }
    script << "unset output\n";
    writeAtomically(studyDir / "plot.gnuplot", script.str());
    const std::string command = "cd '" + studyDir.string() + "' && gnuplot plot.gnuplot > plot.log 2>&1";
    if (std::system(command.c_str()) != 0)
        return "gnuplot failed (see " + (studyDir / "plot.log").string() + "): plots skipped";
    std::string made;
    for (const char* png : {"errorVsCpu.png", "errorVsResolution.png"}) {
        const fs::path tmp = studyDir / (std::string(png) + ".tmp");
        if (fs::exists(tmp)) {
            fs::rename(tmp, studyDir / png);
            made += (made.empty() ? "" : ", ") + std::string(png);
        }
    }
    return "plots: " + made;
}

void report(const fs::path& studyDir, const Study& study, const std::vector<Outcome>& outcomes) {
    std::vector<std::string> normOrder, referenceOrder;
    std::vector<Result> results(study.variants.size());
    for (std::size_t i = 0; i < study.variants.size(); ++i)
        if (fs::exists(studyDir / study.variants[i].name))
            results[i] =
                collect(studyDir / study.variants[i].name, study.application, normOrder, referenceOrder);
    // The studyDict's quantities of each finished run: values without an exact one, extrapolated
    // in the table of compared values.
    for (const auto& [name, command] : study.quantities) {
        if (std::find(referenceOrder.begin(), referenceOrder.end(), name) == referenceOrder.end())
            referenceOrder.push_back(name);
        for (std::size_t i = 0; i < study.variants.size(); ++i) {
            if (!outcomes[i].finished) continue;
            const std::string run = "cd '" + (studyDir / study.variants[i].name).string() + "' && { " +
                                    command + "; } 2> /dev/null";
            std::string last;
            if (FILE* out = popen(run.c_str(), "r")) {
                char buffer[4096];
                while (std::fgets(buffer, sizeof buffer, out)) {
                    std::string text(buffer);
                    while (!text.empty() && (text.back() == '\n' || text.back() == '\r')) text.pop_back();
                    if (!text.empty()) last = text;
                }
                pclose(out);
            }
            const double value = toNumber(last);
            if (std::isfinite(value))
                results[i].references[name] = {value, NAN};
            else
                std::cout << "Warning: quantity " << name << " of " << study.variants[i].name
                          << ": its command gave no number (last line '" << last << "')\n";
        }
    }
    std::string measure = study.measure;
    if (measure.empty() && !normOrder.empty()) measure = normOrder.front();
    if (measure.empty() && !referenceOrder.empty()) measure = referenceOrder.front();
    const bool measured =
        std::find(normOrder.begin(), normOrder.end(), measure) != normOrder.end() ||
        std::find(referenceOrder.begin(), referenceOrder.end(), measure) != referenceOrder.end();
    if (!measure.empty() && !measured && (!normOrder.empty() || !referenceOrder.empty())) {
        std::vector<std::string> all(normOrder);
        all.insert(all.end(), referenceOrder.begin(), referenceOrder.end());
        std::cout << "Warning: no run reported studyDict's error '" << measure
                  << "'; the runs report: " << joined(all) << "\n";
    }

    const std::size_t n = study.variants.size();
    std::vector<double> h(n, NAN), cpu(n, NAN), error(n, NAN), relative(n, NAN);
    for (std::size_t i = 0; i < n; ++i) {
        if (study.variants[i].spacing) h[i] = *study.variants[i].spacing;
        if (!outcomes[i].finished) continue;
        cpu[i] = outcomes[i].cpuSeconds;
        error[i] = measureOf(results[i], measure);
        relative[i] = relativeOf(results[i], measure);
    }
    const auto front = study::paretoFront(cpu, error);

    // One line per scheme, its runs from coarse to fine.
    std::vector<SchemeLine> lines;
    for (std::size_t i = 0; i < n; ++i) {
        auto it = std::find_if(lines.begin(), lines.end(),
                               [&](const SchemeLine& l) { return l.scheme == study.variants[i].scheme; });
        if (it == lines.end()) {
            lines.push_back({study.variants[i].scheme, {}, {}, {}, {}, {}});
            it = lines.end() - 1;
        }
        if (outcomes[i].finished) it->runs.push_back(i);
    }
    for (auto& line : lines) {
        std::sort(line.runs.begin(), line.runs.end(),
                  [&](std::size_t a, std::size_t b) { return h[a] > h[b]; });
        std::vector<double> lh, lc, le;
        for (std::size_t i : line.runs) lh.push_back(h[i]), lc.push_back(cpu[i]), le.push_back(error[i]);
        line.orderH = study::logLogSlope(lh, le);
        line.orderCpu = study::logLogSlope(lc, le);
        const std::size_t k = lh.size();
        if (k >= 3 && std::isfinite(lh[k - 1]))
            line.extrapolation =
                study::richardson(lh[k - 3], le[k - 3], lh[k - 2], le[k - 2], lh[k - 1], le[k - 1]);
        std::vector<std::size_t> byCost(line.runs);
        std::sort(byCost.begin(), byCost.end(),
                  [&](std::size_t a, std::size_t b) { return cpu[a] < cpu[b]; });
        // The targets are on the relative error: an absolute norm's 1e-2 means nothing apart from its units.
        std::vector<double> sc, se;
        for (std::size_t i : byCost) sc.push_back(cpu[i]), se.push_back(relative[i]);
        for (double t : targets) line.cpuToTarget.push_back(study::costToReach(sc, se, t));
    }

    // results.csv: one row per variant, failures included with their diagnosis.
    std::ostringstream csv;
    csv << "variant,scheme,h,status,cpuSeconds,wallSeconds,steps,particles,peakMemoryMiB,measure,error,"
           "relativeError";
    for (const auto& k : normOrder) csv << "," << k;
    for (const auto& k : referenceOrder) csv << "," << k << "," << k << "/exact";
    // The scheme's CPU time to each target, on each of its rows (the figure codes are compared by).
    for (double t : targets) csv << ",schemeCpuSecondsTo" << targetName(t);
    csv << ",pareto,diagnosis\n";
    const auto status = [&](std::size_t i) {
        return outcomes[i].finished            ? std::string("finished")
               : outcomes[i].diagnosis.empty() ? "not run"
                                               : "failed";
    };
    for (std::size_t i = 0; i < n; ++i) {
        const Result& r = results[i];
        const bool onFront = std::find(front.begin(), front.end(), i) != front.end();
        const double memory = std::isfinite(r.peakMemoryBytes) ? r.peakMemoryBytes : outcomes[i].maxRssBytes;
        csv << study.variants[i].name << "," << csvQuoted(study.variants[i].scheme) << ","
            << (std::isfinite(h[i]) ? number(h[i]) : "") << "," << status(i) << ","
            << (outcomes[i].finished ? number(outcomes[i].cpuSeconds) : "") << ","
            << (std::isfinite(r.wallSeconds) ? number(r.wallSeconds) : "") << ","
            << (std::isfinite(r.steps) ? number(r.steps) : "") << ","
            << (std::isfinite(r.particles) ? number(r.particles) : "") << ","
            << (outcomes[i].finished && memory > 0 ? number(memory / 1048576.0) : "") << "," << measure << ","
            << (std::isfinite(error[i]) ? number(error[i]) : "") << ","
            << (std::isfinite(relative[i]) ? number(relative[i]) : "");
        for (const auto& k : normOrder) csv << "," << (r.norms.count(k) ? number(r.norms.at(k)) : "");
        for (const auto& k : referenceOrder)
            csv << "," << (r.references.count(k) ? number(r.references.at(k).value) : "") << ","
                << (r.references.count(k) ? number(r.references.at(k).exact) : "");
        const auto line = std::find_if(lines.begin(), lines.end(), [&](const SchemeLine& l) {
            return l.scheme == study.variants[i].scheme;
        });
        for (std::size_t k = 0; k < targets.size(); ++k)
            csv << "," << (line != lines.end() && line->cpuToTarget[k] ? number(*line->cpuToTarget[k]) : "");
        csv << "," << (onFront ? "yes" : "no") << "," << csvQuoted(outcomes[i].diagnosis) << "\n";
    }
    writeAtomically(studyDir / "results.csv", csv.str());

    // results.md: the runs, then one row per scheme with its orders, extrapolation and cost to targets.
    std::ostringstream md;
    md << "# Study of " << studyDir.parent_path().filename().string() << "\n\nMeasure: `" << measure
       << "`. CPU time: user + system of the variant's whole run (particleGen and " << study.application
       << "). Pareto: no other run is both cheaper and more accurate. Relative error: the measure "
          "over the same norm of the exact field (a value: |value - exact|/|exact|), from the run's "
          "summary. CPU s to 10%, 1%, 0.1%: the CPU time at which the scheme's line of runs, in order "
          "of cost, first reaches that relative error, interpolated in log-log between the two runs "
          "either side (empty: no run reached it).\n\n"
       << "| variant | h | status | CPU s | wall s | steps | particles | peak MiB | " << measure
       << " | Pareto | diagnosis |\n"
       << "|---|---|---|---|---|---|---|---|---|---|---|\n";
    for (std::size_t i = 0; i < n; ++i) {
        const Result& r = results[i];
        const double memory = std::isfinite(r.peakMemoryBytes) ? r.peakMemoryBytes : outcomes[i].maxRssBytes;
        const bool onFront = std::find(front.begin(), front.end(), i) != front.end();
        md << "| " << study.variants[i].name << " | " << shortNumber(h[i]) << " | " << status(i) << " | "
           << (outcomes[i].finished ? shortNumber(outcomes[i].cpuSeconds) : "") << " | "
           << shortNumber(r.wallSeconds) << " | " << shortNumber(r.steps) << " | " << shortNumber(r.particles)
           << " | " << (outcomes[i].finished && memory > 0 ? shortNumber(memory / 1048576.0) : "") << " | "
           << shortNumber(error[i]) << " | " << (onFront ? "yes" : "") << " | "
           << markdownCell(outcomes[i].diagnosis) << " |\n";
    }
    md << "\n| scheme | runs | order in h (fit) | order in CPU (fit) | Richardson order | extrapolated "
       << measure << " | finest relative error";
    for (double t : targets) md << " | CPU s to " << targetName(t);
    md << " |\n|---|---|---|---|---|---|---|---|---|---|\n";
    std::cout << "\n";
    for (const auto& line : lines) {
        md << "| " << line.scheme << " | " << line.runs.size() << " | "
           << (line.orderH ? shortNumber(*line.orderH) : "") << " | "
           << (line.orderCpu ? shortNumber(-*line.orderCpu) : "") << " | "
           << (line.extrapolation ? shortNumber(line.extrapolation->order) : "") << " | "
           << (line.extrapolation ? shortNumber(line.extrapolation->extrapolated) : "") << " | "
           << (line.runs.empty() ? "" : shortNumber(relative[line.runs.back()]));
        for (const auto& c : line.cpuToTarget) md << " | " << (c ? shortNumber(*c) : "");
        md << " |\n";
        std::cout << "scheme " << line.scheme << ": " << line.runs.size() << " runs";
        if (line.orderH) std::cout << ", observed order in h " << shortNumber(*line.orderH);
        if (line.orderCpu) std::cout << ", in CPU time " << shortNumber(-*line.orderCpu);
        if (line.extrapolation)
            std::cout << ", Richardson order " << shortNumber(line.extrapolation->order) << " extrapolated "
                      << shortNumber(line.extrapolation->extrapolated);
        for (std::size_t k = 0; k < targets.size(); ++k)
            if (line.cpuToTarget[k])
                std::cout << ", " << targetName(targets[k]) << " at " << shortNumber(*line.cpuToTarget[k])
                          << " s CPU";
        std::cout << "\n";
    }
    // Every value the runs compare with an exact one, extrapolated where three levels allow.
    std::ostringstream refs;
    for (const auto& key : referenceOrder)
        for (const auto& line : lines) {
            std::vector<double> lh, q;
            double exact = NAN;
            for (std::size_t i : line.runs)
                if (results[i].references.count(key) && std::isfinite(h[i])) {
                    lh.push_back(h[i]);
                    q.push_back(results[i].references.at(key).value);
                    exact = results[i].references.at(key).exact;
                }
            const std::size_t k = lh.size();
            if (k < 3) continue;
            const auto e = study::richardson(lh[k - 3], q[k - 3], lh[k - 2], q[k - 2], lh[k - 1], q[k - 1]);
            refs << "| " << key << " | " << line.scheme << " | " << shortNumber(q[k - 1]) << " | "
                 << (e ? shortNumber(e->extrapolated) : "not monotone") << " | "
                 << (e ? shortNumber(e->order) : "") << " | " << shortNumber(exact) << " |\n";
        }
    if (!refs.str().empty())
        md << "\n| quantity | scheme | finest | Richardson extrapolated | observed order | exact |\n"
           << "|---|---|---|---|---|---|\n"
           << refs.str();
    const std::string plotted = plot(studyDir, measure, lines, h, cpu, error, front);
    md << "\n" << plotted << "\n";
    writeAtomically(studyDir / "results.md", md.str());
    const auto failed = std::count_if(outcomes.begin(), outcomes.end(),
                                      [](const Outcome& o) { return !o.diagnosis.empty(); });
    if (failed) std::cout << failed << " of " << n << " variants failed: their rows give the diagnosis\n";
    std::cout << "Wrote " << (studyDir / "results.csv").string() << " and "
              << (studyDir / "results.md").string() << "\n"
              << plotted << "\n";
}

}  // namespace

int main(int argc, char** argv) {
    const ApplicationInfo info{
        "mfStudy",
        "Run the case as a study from system/studyDict: each variant in study/<variant>/, results in\n"
        "study/results.csv and study/results.md, figures study/errorVsCpu.png and errorVsResolution.png.\n\n"
        "system/studyDict (every entry path is <file under the case>/<scoped entry>, as mfDictionary "
        "reads):\n"
        "    run        auto;        // auto: the case's Allrun if it has one, else particleGen (with a\n"
        "                            // particleGenDict) and controlDict's application | allrun | "
        "application\n"
        "    jobs       1;           // variants run side by side (-jobs overrides)\n"
        "    error      riemann/density/L1;   // the measure fitted and plotted: "
        "<functionObject>/<field>/<L1|L2|Linf>\n"
        "                            // or <functionObject>/<quantity> (|value - exact|/|exact| of a "
        "Diagnostics line)\n"
        "    variants   { a { constant/sphProperties/kernel/type gaussian; } b { ... } }   // named sets of "
        "entries\n"
        "    axes       { kernel { entry constant/sphProperties/kernel/type; values (gaussian wendlandC2); } "
        "}\n"
        "    resolution\n"
        "    {\n"
        "        spacing (0.01 0.005 0.0025);                  // h of each level\n"
        "        scale                                         // entries that follow h\n"
        "        {\n"
        "            system/particleGenDict/regions/left/lattice/spacing 1;   // value = factor h\n"
        "            system/controlDict/deltaT (0.04 1);                     // value = factor h^power\n"
        "            system/particleGenDict/regions/cube/lattice/points (1 -1 1);\n"
        "                // value = factor h^power + offset; on a list of numbers, every component\n"
        "                // (rounded where they are whole): points (9 9 9) at h = 0.125;\n"
        "                // ((10 -1 1) 3 3): a rule per component, a number a constant\n"
        "        }\n"
        "    }\n"
        "    quantities { twist \"awk -F, -f twistAngle.awk postProcessing/top/0/probes.csv | tail -n 1 | "
        "cut "
        "-d, -f2\"; }\n"
        "                // values no summary prints: each command's last line of output in a finished\n"
        "                // variant's directory, extrapolated with the compared values\n"
        "Variants are the product variants x axes x resolution. A finished variant (study/<v>/mfStudy.done,\n"
        "written after a successful run) is not rerun unless studyDict has changed its entries or a file\n"
        "of the base case that the variants copy has changed (the marker holds their fingerprint;\n"
        "studyDict itself is left out of it); one that\n"
        "failed or was stopped runs again from the case; one study of a case runs at a time. A failed\n"
        "variant is a row with the first error line of its logs. studyDict is checked against the case\n"
        "before anything runs: a path that is not in the case, an empty list or a value of the wrong form\n"
        "is an error with its file and line, exit status 1. Without gnuplot the plots are skipped.\n"
        "Each scheme's CPU time to a relative error of 10%, 1% and 0.1% (the summary's error lines give\n"
        "the exact norms) is interpolated on its line of runs, in results.md and results.csv.",
        {{"jobs", "N", "variants run side by side (default: studyDict's jobs, else 1)"},
         {"list", "", "print the variants and the entries each sets, then stop (nothing is written)"}},
        {},
        true};
    return runApplication(argc, argv, info, [](const Arguments& args) {
        const fs::path root = fs::absolute(args.caseDir()).lexically_normal();
        std::optional<int> jobs;
        if (auto j = args.find("jobs")) {
            char* end = nullptr;
            const long v = std::strtol(j->c_str(), &end, 10);
            if (end == j->c_str() || *end != '\0' || v < 1)
                throw InputError("-jobs '" + *j + "' is not a count of at least 1");
            jobs = int(v);
        }
        const Study study = readStudy(root, jobs);
        std::cout << "mfStudy: " << study.variants.size() << " variants of " << root.string() << ", "
                  << study.jobs << " at a time, run by "
                  << (study.mode == RunMode::allrun ? std::string("the case's Allrun")
                                                    : "particleGen and " + study.application)
                  << "\n";
        if (args.has("list")) {
            for (const auto& v : study.variants) {
                std::cout << "    " << v.name << "\n";
                for (const auto& s : v.settings) std::cout << "        " << s.path << " " << s.value << "\n";
            }
            return 0;
        }
        const fs::path studyDir = root / "study";
        fs::create_directories(studyDir);
        // One study of a case at a time: two would run the same variants into the same directories.
        const CaseLock lock(studyDir, "mfStudy");
        std::vector<Outcome> outcomes(study.variants.size());
        const int stopped = runVariants(studyDir, study, outcomes);
        report(studyDir, study, outcomes);
        return stopped;
    });
}
