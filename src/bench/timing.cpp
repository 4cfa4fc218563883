#include "bench/timing.h"

#include <algorithm>
#include <exception>

namespace simeco::bench {

double median(std::vector<double> values) {
    if (values.empty()) {
        return 0;
    }
    std::sort(values.begin(), values.end());
    std::size_t mid = values.size() / 2;
    return values.size() % 2 == 1 ? values[mid] : 0.5 * (values[mid - 1] + values[mid]);
}

std::vector<double> repeatRuns(int warmUp, int repeat, const std::function<double()>& run) {
    for (int i = 0; i < warmUp; ++i) {
        run();
    }
    std::vector<double> samples;
    samples.reserve(static_cast<std::size_t>(std::max(repeat, 0)));
    for (int i = 0; i < repeat; ++i) {
        samples.push_back(run());
    }
    return samples;
}

void runInTurns(int warmUp, int repeat, const std::vector<Measurement*>& measurements) {
    for (int round = 0; round < warmUp + repeat; ++round) {
        for (Measurement* m : measurements) {
            if (!m->error.empty()) {
                continue;
            }
            try {
                double value = m->run();
                if (round >= warmUp) {
                    m->samples.push_back(value);
                }
            } catch (const std::exception& e) {
                m->error = *e.what() ? e.what() : "failed";
            }
        }
    }
}

} // namespace simeco::bench
