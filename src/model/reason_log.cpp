#include "model/reason_log.h"

namespace urbis {

std::string osmRefName(OsmRef ref) {
    const char type = ref.type == OsmType::Node ? 'n' : ref.type == OsmType::Way ? 'w' : 'r';
    return type + std::to_string(ref.id);
}

void record(ReasonLog& log, const std::string& reason, OsmRef id, uint64_t n) {
    ReasonEntry& entry = log[reason];
    entry.count += n;
    entry.ids.push_back(id);
}

void recordCount(ReasonLog& log, const std::string& reason, uint64_t n) { log[reason].count += n; }

uint64_t countOf(const ReasonLog& log, const std::string& reason) {
    const auto it = log.find(reason);
    return it == log.end() ? 0 : it->second.count;
}

} // namespace urbis
