#pragma once
// How contacts respond (CONTRACT §6, simulation.contact_model): the lecture's three answers to
// a collision, switched live.
//   impulse    the contact solver after the smooth step (ContactSolver): stacks rest
//   penalty    a damped spring per overlapping point, a smooth force inside the integrator
//              (PenaltyContacts)
//   kinematic  move the bodies apart and reflect the approaching velocity (KinematicResponse)

#include <array>
#include <optional>
#include <string>
#include <string_view>

namespace phasebox {

enum class ContactModel : unsigned char { Impulse, Penalty, Kinematic };

inline constexpr std::array<std::string_view, 3> kContactModelNames = {"impulse", "penalty",
                                                                       "kinematic"};

inline std::string_view contactModelName(ContactModel model) {
    return kContactModelNames[static_cast<int>(model)];
}

inline std::optional<ContactModel> contactModelFromName(std::string_view name) {
    for (int i = 0; i < static_cast<int>(kContactModelNames.size()); ++i)
        if (kContactModelNames[i] == name) return static_cast<ContactModel>(i);
    return std::nullopt;
}

// "impulse, penalty, kinematic": for messages that list the known models.
inline std::string knownContactModelNames() {
    std::string list;
    for (std::string_view name : kContactModelNames) {
        if (!list.empty()) list += ", ";
        list += name;
    }
    return list;
}

}  // namespace phasebox
