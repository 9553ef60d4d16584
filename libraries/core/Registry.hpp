#pragma once
// Runtime selection. A model family is an abstract base that declares
//
//     static constexpr const char* familyName = "equationOfState";
//     using Selector = mfdyn::Registry<EquationOfState, const Dictionary&>;
//     static std::unique_ptr<EquationOfState> New(const Dictionary& dict) { return Selector::New(dict); }
//
// (Selector::New(dict, rest...) reads `type` from dict and constructs Derived(dict, rest...).)
//
// and a model registers itself with one line at the end of its own .cpp:
//
//     MFDYN_REGISTER(EquationOfState, MieGruneisen, "mieGruneisen", "Mie-Grüneisen EOS on a linear Us-up
//     Hugoniot");
//
// The tables live in one place in libmfdyn_core (RegistryIndex), keyed by family name, so a
// model registered by a user library loaded with dlopen lands in the same table the solver reads,
// whatever the symbol visibility of template statics. Each item records the shared object that
// registered it (dladdr), so listings and duplicate-name errors name libraries, and the source
// file of the model (__FILE__, relative to the source tree) for the generated docs (mfDoc). A
// model that declares `static KeywordSchema keywords()` (core/KeywordSchema.hpp) registers it
// with the same line: -listModels, -describe and mfDoc show its keywords.
//
// A family that belongs to one method declares its method next to its name:
//
//     static constexpr const char* familyName = "dissipation";
//     static constexpr const char* methodName = "tlSph";
//
// The index keys families by (method, name), so tlSph's dissipation and impactSph's dissipation
// are two families a user writes as `dissipation { type ...; }` in either properties dictionary,
// with no prefix. Listings and messages name a scoped family "dissipation (tlSph)";
// `-describe dissipation` shows every family of that name, `-describe tlSph/dissipation` one, and
// `-describe tlSph/dissipation/jst` one type of it. A family without methodName is shared by
// every method, as before.
#include "core/Dictionary.hpp"
#include "core/KeywordSchema.hpp"

#include <concepts>
#include <functional>
#include <memory>
#include <string>
#include <typeinfo>
#include <vector>

namespace mfdyn {

struct RegistryItem {
    std::string name;
    std::string description;
    std::string library;               // shared object or executable that registered it
    std::shared_ptr<const void> make;  // std::function<std::unique_ptr<Base>(Args...)>
    // typeid name of the factory: a family templated on the dimension (Strength<Dim>) keeps one
    // item per name and dimension under one family name.
    std::string signature;
    // The model's source file, relative to the source tree when it was built there
    // ("libraries/materials/equationOfState/MieGruneisen.cpp"); absolute for a user library.
    std::string sourceFile;
    // Its keyword schema, when the model declares `static KeywordSchema keywords()`.
    KeywordSchema (*keywords)() = nullptr;
    // 1, 2 or 3 for a family templated on the dimension (one item per dimension), else 0.
    int dimension = 0;
    // A solver's properties dictionary ("sphProperties", read from constant/), when it names it
    // (solver/SolverRegistry.hpp); empty for models, which are read from a sub-dictionary.
    std::string dictionary;
};

struct RegistryFamily {
    std::string name;
    std::string method;               // the methodName of a method-scoped family; empty for a shared one
    std::vector<RegistryItem> items;  // sorted by name
    std::vector<std::string> conflicts;

    // "dissipation (tlSph)" for a scoped family, "equationOfState" for a shared one: what listings
    // and messages call it.
    std::string title() const;
    // "tlSph/dissipation" or "equationOfState": how -describe names it, and mfDoc's directory.
    std::string key() const;

    const RegistryItem* find(std::string_view type, std::string_view signature = {}) const;
    // Type names, each once, sorted.
    std::vector<std::string> names() const;
    // "unknown equationOfState type 'mieGrunesen'; did you mean 'mieGruneisen'? Valid types: ..."
    std::string unknownTypeMessage(std::string_view type) const;
    // "\n    valid kernel types:\n        cubicSpline  (libmfdyn_kernels.so)\n ..."
    std::string validTypes() const;
};

class RegistryIndex {
public:
    static RegistryIndex& global();
    // The family (method, name), made empty when first asked for; method "" is a shared family.
    RegistryFamily& family(std::string_view name, std::string_view method = {});
    const RegistryFamily* findFamily(std::string_view name, std::string_view method = {}) const;
    // Every family called `name`, whatever its method (shared first, then by method).
    std::vector<const RegistryFamily*> familiesNamed(std::string_view name) const;
    // Sorted by name, then method (a shared family before the scoped ones of its name).
    std::vector<const RegistryFamily*> families() const;
    void add(std::string_view family, RegistryItem item, std::string_view method = {});
    // Throws Error naming both libraries if any name was registered twice.
    void checkConflicts() const;
    // Text for -listModels: every family and its types with descriptions, and the keywords of
    // each type that declares a schema (name, unit, required or default, bounds or words). With
    // `solver` (the application's own, in the family "solver"), that solver's keywords come first.
    std::string listing(std::string_view solver = {}) const;
    // Text for -describe <what>: `what` is a family ("equationOfState": its listing; "dissipation":
    // the listing of every family of that name; "tlSph/dissipation": one scoped family), a type
    // ("mieGruneisen", or "equationOfState/mieGruneisen" where a name is in several families, or
    // "tlSph/dissipation/jst": the description, source file, library, dimensions and every keyword
    // with its meaning). Throws InputError listing the families when nothing matches.
    std::string describe(std::string_view what) const;

private:
    std::vector<std::unique_ptr<RegistryFamily>> families_;
};

// `file` (a __FILE__) relative to the source tree libmfdyn_core was built from, when inside it; a
// relative __FILE__ (as ccache's base_dir makes it) without its leading "..".
std::string sourceFileRelative(const char* file);

// The shared object holding `address` ("libmfdyn_core.so", "libmyModels.so", or the program).
std::string sharedObjectOf(const void* address);

// The methodName of a family base, or "" when it declares none (a family shared by all methods).
template <class Base>
constexpr const char* methodNameOf() {
    if constexpr (requires { Base::methodName; })
        return Base::methodName;
    else
        return "";
}

// What listings and messages call the family of Base: "dissipation (tlSph)" or "equationOfState".
template <class Base>
std::string familyTitle() {
    const std::string method = methodNameOf<Base>();
    return std::string(Base::familyName) + (method.empty() ? "" : " (" + method + ")");
}

template <class Base, class... Args>
class Registry {
public:
    using Factory = std::function<std::unique_ptr<Base>(Args...)>;

    static void add(const std::string& name, const std::string& description, Factory make,
                    const void* registrant, const char* sourceFile = "",
                    KeywordSchema (*keywords)() = nullptr, int dimension = 0) {
        RegistryIndex::global().add(
            Base::familyName,
            RegistryItem{name, description, sharedObjectOf(registrant),
                         std::make_shared<const Factory>(std::move(make)), typeid(Factory).name(),
                         sourceFileRelative(sourceFile), keywords, dimension},
            methodNameOf<Base>());
    }

    // Select by the `type` entry of `dict`, which is passed on as the first constructor argument
    // (families whose constructor starts with const Dictionary&); `rest` are the other arguments.
    template <class... Rest>
    static std::unique_ptr<Base> New(const Dictionary& dict, Rest&&... rest) {
        if (!dict.found("type")) {
            const RegistryFamily& fam =
                RegistryIndex::global().family(Base::familyName, methodNameOf<Base>());
            throw InputError(dict.where(), dict.scope(), "missing keyword 'type'" + fam.validTypes());
        }
        return NewOfType(dict.get<std::string>("type"), dict, dict, std::forward<Rest>(rest)...);
    }

    // Select by an explicit type name; `context` locates the error message.
    static std::unique_ptr<Base> NewOfType(const std::string& type, const Dictionary& context, Args... args) {
        RegistryIndex::global().checkConflicts();
        const RegistryFamily& fam = RegistryIndex::global().family(Base::familyName, methodNameOf<Base>());
        const RegistryItem* item = fam.find(type, typeid(Factory).name());
        if (!item) {
            if (context.found("type")) throw context.error("type", fam.unknownTypeMessage(type));
            throw InputError(context.where(), context.scope(), fam.unknownTypeMessage(type));
        }
        return (*static_cast<const Factory*>(item->make.get()))(std::forward<Args>(args)...);
    }

    static std::vector<std::string> names() {
        return RegistryIndex::global().family(Base::familyName, methodNameOf<Base>()).names();
    }
};

// Registration object: one static per model, made by MFDYN_REGISTER. A model that declares
// `static KeywordSchema keywords()` registers its schema with it (core/KeywordSchema.hpp).
template <class Base, class Derived>
struct Registration {
    Registration(const char* name, const char* description, const char* sourceFile = "", int dimension = 0) {
        register_(name, description, sourceFile, dimension, static_cast<typename Base::Selector*>(nullptr));
    }

private:
    template <class... Args>
    void register_(const char* name, const char* description, const char* sourceFile, int dimension,
                   Registry<Base, Args...>*) {
        KeywordSchema (*keywords)() = nullptr;
        if constexpr (requires {
                          { Derived::keywords() } -> std::same_as<KeywordSchema>;
                      })
            keywords = &Derived::keywords;
        Registry<Base, Args...>::add(
            name, description,
            [](Args... args) -> std::unique_ptr<Base> {
                return std::make_unique<Derived>(std::forward<Args>(args)...);
            },
            this, sourceFile, keywords, dimension);
    }
};

#define MFDYN_CONCAT_IMPL(a, b) a##b
#define MFDYN_CONCAT(a, b) MFDYN_CONCAT_IMPL(a, b)
#define MFDYN_REGISTER(Base, Derived, name, description)                                           \
    static const ::mfdyn::Registration<Base, Derived> MFDYN_CONCAT(mfdynRegistration_, __LINE__) { \
        name, description, __FILE__                                                                \
    }

// For families templated on the space dimension (template <int Dim> class Strength): registers
// Derived<1>, <2>, <3> under one name.
#define MFDYN_REGISTER_DIM(Base, Derived, name, description)                                              \
    static const ::mfdyn::Registration<Base<1>, Derived<1>> MFDYN_CONCAT(mfdynRegistration1_, __LINE__){  \
        name, description, __FILE__, 1};                                                                  \
    static const ::mfdyn::Registration<Base<2>, Derived<2>> MFDYN_CONCAT(mfdynRegistration2_, __LINE__){  \
        name, description, __FILE__, 2};                                                                  \
    static const ::mfdyn::Registration<Base<3>, Derived<3>> MFDYN_CONCAT(mfdynRegistration3_, __LINE__) { \
        name, description, __FILE__, 3                                                                    \
    }

}  // namespace mfdyn
