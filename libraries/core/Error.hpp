#pragma once
// Errors of mfdyn. Every failure is an exception derived from mfdyn::Error; each application
// catches it at the top, prints the message and exits with status 1 (see Application.hpp).
#include <memory>
#include <stdexcept>
#include <string>

namespace mfdyn {

// A place in an input file: file name, 1-based line and column. An empty file means "no place".
struct SourceLocation {
    std::shared_ptr<const std::string> file;
    int line = 0;
    int column = 0;

    bool known() const { return file && line > 0; }
    // "system/controlDict:12:5", or "" when unknown.
    std::string str() const;
};

class Error : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

// Bad input: a dictionary, a particle file, a command-line argument. The message reads
// "file:line:column: in scope 'a/b/c': what was expected, what was found".
class InputError : public Error {
public:
    InputError(const SourceLocation& where, const std::string& scope, const std::string& message);
    explicit InputError(const std::string& message) : Error(message) {}
};

// A run that cannot go on (NaN, negative density, collapsed time step). The solver writes its
// state before throwing it.
class RunError : public Error {
public:
    using Error::Error;
};

}  // namespace mfdyn
