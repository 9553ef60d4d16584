// kernelSpectrum: the Fourier transform of a smoothing kernel in 1, 2 or 3 dimensions, written as CSV
// (k, W_hat) and plotted with gnuplot, with the verdict whether the kernel is positive definite
// (Dehnen & Aly 2012: a negative W_hat permits the pairing instability). The numerics, their error
// estimate and the tolerance of the verdict are those of kernels/KernelSpectrum.hpp.
//
//     kernelSpectrum -kernel wendlandC2 -dim 3 [-h 1] [-kMax 100] [-samples 256] [-output dir]
//     kernelSpectrum -dict spectrumDict      // `kernel { type ...; }` plus optional dim, h, kMax, samples,
//     output
#include "kernels/KernelSpectrum.hpp"
#include "core/Application.hpp"
#include "core/Dictionary.hpp"
#include "core/Error.hpp"
#include "kernels/Kernel.hpp"

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <sstream>

namespace fs = std::filesystem;
using namespace mfdyn;

namespace {

// Looked up on PATH rather than assumed, so a machine without gnuplot still gets its CSV.
std::optional<fs::path> findProgram(const std::string& name) {
    const char* path = std::getenv("PATH");
    if (!path) return std::nullopt;
    std::stringstream dirs(path);
    std::string dir;
    while (std::getline(dirs, dir, ':')) {
        const fs::path candidate = fs::path(dir.empty() ? "." : dir) / name;
        std::error_code ec;
        if (fs::is_regular_file(candidate, ec) &&
            (fs::status(candidate, ec).permissions() & fs::perms::owner_exec) != fs::perms::none)
            return candidate;
    }
    return std::nullopt;
}

double parseNumber(const std::string& option, const std::string& text) {
    std::size_t used = 0;
    double value = 0.0;
    try {
        value = std::stod(text, &used);
    } catch (const std::exception&) {
        used = 0;
    }
    if (used != text.size())
        throw InputError("option -" + option + ": expected a number, found '" + text + "'");
    return value;
}

void writeCsv(const fs::path& file, const KernelSpectrum& spectrum) {
    std::ofstream out(file);
    if (!out) throw Error("cannot write '" + file.string() + "'");
    out << "k,W_hat\n" << std::setprecision(17);
    for (std::size_t m = 0; m < spectrum.k().size(); ++m)
        out << spectrum.k()[m] << ',' << spectrum.values()[m] << '\n';
    if (!out) throw Error("cannot write '" + file.string() + "'");
}

// Linear W_hat above, |W_hat| on a log scale below with the negative part in red: the lobes that
// decide the verdict are invisible on the linear plot.
void writeGnuplotScript(const fs::path& script, const fs::path& csv, const fs::path& png,
                        const std::string& title, double h) {
    std::ofstream out(script);
    if (!out) throw Error("cannot write '" + script.string() + "'");
    out << "set terminal pngcairo size 900,900 enhanced font ',11'\n"
        << "set output '" << png.string() << "'\n"
        << "set datafile separator ','\n"
        << "set multiplot layout 2,1 title '" << title << "'\n"
        << "set xlabel 'k h'\nset ylabel 'Ŵ(k)'\nset grid\nset xzeroaxis lt -1\n"
        << "plot '" << csv.string() << "' every ::1 using ($1*" << h << "):2 with lines lw 2 title 'Ŵ(k)'\n"
        << "set logscale y\nset ylabel '|Ŵ(k)|'\nset format y '10^{%L}'\n"
        << "plot '" << csv.string() << "' every ::1 using ($1*" << h
        << "):($2 > 0 ? $2 : 1/0) with points pt 7 ps 0.3 "
        << "lc rgb 'blue' title 'Ŵ > 0', \\\n"
        << "     '" << csv.string() << "' every ::1 using ($1*" << h
        << "):($2 < 0 ? -$2 : 1/0) with points pt 7 ps 0.5 "
        << "lc rgb 'red' title 'Ŵ < 0'\n"
        << "unset multiplot\n";
}

}  // namespace

int main(int argc, char** argv) {
    ApplicationInfo info{
        "kernelSpectrum",
        "Fourier transform of a smoothing kernel (CSV and PNG) and whether it is positive definite.",
        {{"kernel", "type", "kernel type, e.g. wendlandC2 (or use -dict)"},
         {"dict", "file",
          "dictionary with a `kernel { type ...; }` entry and optional dim, h, "
          "kMax, samples, output"},
         {"dim", "d", "dimension 1, 2 or 3 (default 3)"},
         {"h", "length", "smoothing length (default 1): k is reported in units of 1/length"},
         {"kMax", "kH", "largest k times support radius H (default 100)"},
         {"samples", "S", "samples over the support radius (default 256, doubled for the error)"},
         {"output", "dir", "directory for <type>_<d>D.csv/.png/.gp (default .)"}},
        {},
        false};
    return runApplication(argc, argv, info, [](const Arguments& args) {
        Dictionary dict;
        if (auto file = args.find("dict")) dict = Dictionary::read(*file);
        if (auto type = args.find("kernel")) {
            dict.remove("kernel");
            dict.set("kernel", "{ type " + *type + "; }");
        }
        if (!dict.found("kernel"))
            throw InputError(
                "give the kernel with -kernel <type> or in a dictionary (-dict) as kernel { type ...; }" +
                RegistryIndex::global().family(Kernel::familyName).validTypes());
        const std::unique_ptr<Kernel> kernel = Kernel::New(dict.subDict("kernel"));

        auto number = [&](const std::string& key, double fallback) {
            if (auto text = args.find(key)) return parseNumber(key, *text);
            return dict.getOrDefault<double>(key, fallback);
        };
        const int dim = int(number("dim", 3));
        if (dim < 1 || dim > 3 || number("dim", 3) != dim) throw InputError("-dim must be 1, 2 or 3");
        const double h = number("h", 1.0);
        if (!(h > 0.0)) throw InputError("-h must be positive");
        SpectrumOptions options;
        options.kMaxH = number("kMax", options.kMaxH);
        options.samplesPerSupport = int(number("samples", options.samplesPerSupport));
        const fs::path outputDir =
            args.find("output").value_or(dict.getOrDefault<std::string>("output", "."));
        fs::create_directories(outputDir);

        const KernelSpectrum spectrum(*kernel, dim, h, options);
        const std::string stem = kernel->type() + "_" + std::to_string(dim) + "D";
        const fs::path csv = outputDir / (stem + ".csv");
        writeCsv(csv, spectrum);

        const double H = kernel->supportRadius(h);
        std::cout << std::setprecision(6) << "kernel          " << kernel->type() << " in " << dim << "D\n"
                  << "h, H = kappa h  " << h << ", " << H << " (kappa " << kernel->kappa() << ")\n"
                  << "c_d             " << std::setprecision(12) << kernel->normalisation(dim)
                  << std::setprecision(6) << " (unit support)\n"
                  << "s_d             " << kernel->secondMoment(dim) << " (sigma = s_d h), s_d/kappa "
                  << kernel->secondMoment(dim) / kernel->kappa() << "\n"
                  << "transform       " << spectrum.method() << ", " << spectrum.k().size()
                  << " wavenumbers, k h <= " << spectrum.k().back() * h << "\n"
                  << "W_hat(0)        " << std::setprecision(15) << spectrum.values().front()
                  << std::setprecision(6) << "\n"
                  << "error estimate  " << spectrum.errorEstimate() << " (S vs 2S samples)\n";
        if (spectrum.truncationBound() > 0.0)
            std::cout << "truncation      " << spectrum.truncationBound()
                      << " (bound on the dip due to truncation)\n";
        std::cout << "min W_hat       " << spectrum.minimum() << " at k h = " << spectrum.kAtMinimum() * h
                  << " (k H = " << spectrum.kAtMinimum() * H << ")\n"
                  << "verdict         "
                  << (spectrum.positiveDefinite() ? "positive definite" : "NOT positive definite")
                  << " (W_hat >= -" << spectrum.tolerance() << " for k H <= " << spectrum.k().back() * H
                  << ")\n"
                  << "csv             " << csv.string() << "\n";

        if (auto gnuplot = findProgram("gnuplot")) {
            const fs::path script = outputDir / (stem + ".gp"), png = outputDir / (stem + ".png");
            std::ostringstream title;
            title << kernel->type() << ", " << dim
                  << "D: " << (spectrum.positiveDefinite() ? "positive definite" : "not positive definite");
            writeGnuplotScript(script, csv, png, title.str(), h);
            const std::string command = "'" + gnuplot->string() + "' '" + script.string() + "'";
            if (std::system(command.c_str()) != 0) throw Error("gnuplot failed on '" + script.string() + "'");
            std::cout << "png             " << png.string() << "\n";
        } else {
            std::cout << "png             skipped: gnuplot was not found on PATH\n";
        }
        return 0;
    });
}
