#pragma once
#include "functionObjects/FunctionObject.hpp"

namespace mfdyn {

// freeSurfaceFront: the surge front and the column height of a collapsing fluid column (the dam
// break of Martin & Moyce 1952); FreeSurfaceFront.cpp documents the keywords and the estimates.
class FreeSurfaceFront final : public FunctionObject {
public:
    FreeSurfaceFront(const Dictionary& dict, const std::string& name, const RunContext& context);
    static KeywordSchema keywords();
    void write() override;
    std::vector<std::string> summary() const override;

private:
    FreeSurfaceFront(const KeywordValues& values, const std::string& name, const RunContext& context);

    std::int64_t region_ = -1;  // -1: every particle
    std::string regionName_;
    double along_[3] = {1, 0, 0};  // the surge's direction (unit)
    double up_[3] = {0, 1, 0};     // against gravity (unit)
    double band_ = 0;              // the wall band's width, m
    double stray_ = 1e-3;          // the mass fraction allowed beyond each estimate
    std::unique_ptr<CsvFile> csv_;
    double front_ = 0, height_ = 0, wall_ = 0, time_ = 0;
    std::size_t writes_ = 0;
};

}  // namespace mfdyn
