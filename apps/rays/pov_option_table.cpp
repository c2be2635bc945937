#include "pov_option_table.h"

#include <unordered_map>

#include "arg_text.h"

namespace rays::cli::pov {
namespace {

// POV-Ray 3.7's INI keys (reference 3.2).
const KeyInfo kKeys[] = {
    {"Input_File_Name", Key::InputFileName, Kind::Text},
    {"Output_File_Name", Key::OutputFileName, Kind::Text},
    {"Width", Key::Width, Kind::Int},
    {"Height", Key::Height, Kind::Int},
    {"Antialias", Key::Antialias, Kind::Bool},
    {"Antialias_Threshold", Key::AntialiasThreshold, Kind::Float},
    {"Antialias_Depth", Key::AntialiasDepth, Kind::Int},
    {"Antialias_Gamma", Key::AntialiasGamma, Kind::Float},
    {"Sampling_Method", Key::SamplingMethod, Kind::Int},
    {"Jitter", Key::Jitter, Kind::Bool},
    {"Jitter_Amount", Key::JitterAmount, Kind::Float},
    {"Library_Path", Key::LibraryPath, Kind::Text},
    {"Declare", Key::Declare, Kind::Text},
    {"Clock", Key::Clock, Kind::Float},
    {"Initial_Frame", Key::InitialFrame, Kind::Int},
    {"Final_Frame", Key::FinalFrame, Kind::Int},
    {"Initial_Clock", Key::InitialClock, Kind::Float},
    {"Final_Clock", Key::FinalClock, Kind::Float},
    {"Subset_Start_Frame", Key::SubsetStartFrame, Kind::Float},
    {"Subset_End_Frame", Key::SubsetEndFrame, Kind::Float},
    {"Frame_Step", Key::FrameStep, Kind::Int},
    {"Cyclic_Animation", Key::CyclicAnimation, Kind::Bool},
    {"Start_Row", Key::StartRow, Kind::Float},
    {"End_Row", Key::EndRow, Kind::Float},
    {"Start_Column", Key::StartColumn, Kind::Float},
    {"End_Column", Key::EndColumn, Kind::Float},
    {"Output_to_File", Key::OutputToFile, Kind::Bool},
    {"Output_File_Type", Key::OutputFileType, Kind::Text},
    {"Output_Alpha", Key::OutputAlpha, Kind::Bool},
    {"Bits_Per_Color", Key::BitsPerColor, Kind::Int},
    {"File_Gamma", Key::FileGamma, Kind::Text},
    {"Include_Header", Key::IncludeHeader, Kind::Text},
    {"Compression", Key::Compression, Kind::Int},
    {"Work_Threads", Key::WorkThreads, Kind::Int},
    {"Continue_Trace", Key::ContinueTrace, Kind::Bool},
    // Accepted, not acted on.
    {"Display", Key::Quiet, Kind::Bool},
    {"Video_Mode", Key::Quiet, Kind::Text},
    {"Palette", Key::Quiet, Kind::Text},
    {"Display_Gamma", Key::Quiet, Kind::Text},
    {"Pause_When_Done", Key::Quiet, Kind::Bool},
    {"Verbose", Key::Quiet, Kind::Bool},
    {"Clockless_Animation", Key::Quiet, Kind::Bool},
    {"Real_Time_Raytracing", Key::Quiet, Kind::Bool},
    {"Draw_Vistas", Key::Quiet, Kind::Bool},
    {"Preview_Start_Size", Key::Quiet, Kind::Int},
    {"Preview_End_Size", Key::Quiet, Kind::Int},
    {"Max_Image_Buffer_Memory", Key::Quiet, Kind::Int},
    {"Buffer_Output", Key::Quiet, Kind::Bool},
    {"Buffer_Size", Key::Quiet, Kind::Int},
    {"Test_Abort", Key::Quiet, Kind::Bool},
    {"Test_Abort_Count", Key::Quiet, Kind::Int},
    {"Odd_Field", Key::Quiet, Kind::Bool},
    {"Quality", Key::Quiet, Kind::Int},
    {"Bounding", Key::Quiet, Kind::Bool},
    {"Bounding_Threshold", Key::Quiet, Kind::Int},
    {"Bounding_Method", Key::Quiet, Kind::Int},
    {"Light_Buffer", Key::Quiet, Kind::Bool},
    {"Vista_Buffer", Key::Quiet, Kind::Bool},
    {"Remove_Bounds", Key::Quiet, Kind::Bool},
    {"Split_Unions", Key::Quiet, Kind::Bool},
    {"BSP_MaxDepth", Key::Quiet, Kind::Int},
    {"BSP_BaseAccessCost", Key::Quiet, Kind::Float},
    {"BSP_ChildAccessCost", Key::Quiet, Kind::Float},
    {"BSP_IsectCost", Key::Quiet, Kind::Float},
    {"BSP_MissChance", Key::Quiet, Kind::Float},
    {"Render_Block_Size", Key::Quiet, Kind::Int},
    {"Render_Pattern", Key::Quiet, Kind::Int},
    {"Render_Block_Step", Key::Quiet, Kind::Int},
    {"High_Reproducibility", Key::Quiet, Kind::Bool},
    {"Radiosity_File_Name", Key::Quiet, Kind::Text},
    {"Radiosity_From_File", Key::Quiet, Kind::Bool},
    {"Radiosity_To_File", Key::Quiet, Kind::Bool},
    {"Radiosity_Vain_Pretrace", Key::Quiet, Kind::Bool},
    {"Debug_Console", Key::Quiet, Kind::Bool},
    {"Fatal_Console", Key::Quiet, Kind::Bool},
    {"Render_Console", Key::Quiet, Kind::Bool},
    {"Statistic_Console", Key::Quiet, Kind::Bool},
    {"Warning_Console", Key::Quiet, Kind::Bool},
    {"All_Console", Key::Quiet, Kind::Bool},
    {"Append_File", Key::Quiet, Kind::Bool},
    {"Warning_Level", Key::Quiet, Kind::Int},
    {"Pre_Scene_Return", Key::Quiet, Kind::Text},
    {"Pre_Frame_Return", Key::Quiet, Kind::Text},
    {"Post_Scene_Return", Key::Quiet, Kind::Text},
    {"Post_Frame_Return", Key::Quiet, Kind::Text},
    {"User_Abort_Return", Key::Quiet, Kind::Text},
    {"Fatal_Error_Return", Key::Quiet, Kind::Text},
    // Accepted with a warning when they ask for something.
    {"Field_Render", Key::Warned, Kind::Bool, "field rendering is not supported; whole frames are rendered"},
    {"Dither", Key::Warned, Kind::Bool, "dithering is not supported"},
    {"Dither_Method", Key::Warned, Kind::Text, "dithering is not supported"},
    {"Version", Key::Version, Kind::Float},
    {"Grayscale_Output", Key::Warned, Kind::Bool, "greyscale output is not supported"},
    {"Create_Ini", Key::Warned, Kind::Text, "no INI file is written"},
    {"Debug_File", Key::Warned, Kind::Text, "messages are not copied to files"},
    {"Fatal_File", Key::Warned, Kind::Text, "messages are not copied to files"},
    {"Render_File", Key::Warned, Kind::Text, "messages are not copied to files"},
    {"Statistic_File", Key::Warned, Kind::Text, "messages are not copied to files"},
    {"Warning_File", Key::Warned, Kind::Text, "messages are not copied to files"},
    {"All_File", Key::Warned, Kind::Text, "messages are not copied to files"},
    {"Pre_Scene_Command", Key::Warned, Kind::Text, "Rays runs no shell commands"},
    {"Pre_Frame_Command", Key::Warned, Kind::Text, "Rays runs no shell commands"},
    {"Post_Scene_Command", Key::Warned, Kind::Text, "Rays runs no shell commands"},
    {"Post_Frame_Command", Key::Warned, Kind::Text, "Rays runs no shell commands"},
    {"User_Abort_Command", Key::Warned, Kind::Text, "Rays runs no shell commands"},
    {"Fatal_Error_Command", Key::Warned, Kind::Text, "Rays runs no shell commands"},
};

// POV-Ray 3.7's switches (reference 3.2); the longest matching letters win (+KFF before +KF).
const SwitchInfo kSwitches[] = {
    {"I", "Input_File_Name", Form::Value},
    {"O", "Output_File_Name", Form::Value},
    {"W", "Width", Form::Value},
    {"H", "Height", Form::Value},
    {"A", "Antialias", Form::OnValue, "Antialias_Threshold"},
    {"AM", "Sampling_Method", Form::Value},
    {"AG", "Antialias_Gamma", Form::Value},
    {"R", "Antialias_Depth", Form::Value},
    {"J", "Jitter", Form::OnValue, "Jitter_Amount"},
    {"L", "Library_Path", Form::Value},
    {"K", "Clock", Form::Value},
    {"KFI", "Initial_Frame", Form::Value},
    {"KFF", "Final_Frame", Form::Value},
    {"KI", "Initial_Clock", Form::Value},
    {"KF", "Final_Clock", Form::Value},
    {"KC", "Cyclic_Animation", Form::Toggle},
    {"SF", "Subset_Start_Frame", Form::Value},
    {"EF", "Subset_End_Frame", Form::Value},
    {"STP", "Frame_Step", Form::Value},
    {"SR", "Start_Row", Form::Value},
    {"ER", "End_Row", Form::Value},
    {"SC", "Start_Column", Form::Value},
    {"EC", "End_Column", Form::Value},
    {"F", "Output_to_File", Form::OnValue, "Output_File_Type"},
    {"UA", "Output_Alpha", Form::Toggle},
    {"UF", "Field_Render", Form::Toggle},
    {"UO", "Odd_Field", Form::Toggle},
    {"C", "Continue_Trace", Form::Toggle},
    {"D", "Display", Form::OnValue, "Video_Mode"},
    {"V", "Verbose", Form::Toggle},
    {"P", "Pause_When_Done", Form::Toggle},
    {"X", "Test_Abort", Form::OnValue, "Test_Abort_Count"},
    {"Q", "Quality", Form::Value},
    {"WT", "Work_Threads", Form::Value},
    {"WL", "Warning_Level", Form::Value},
    {"MB", "Bounding", Form::OnValue, "Bounding_Threshold"},
    {"MI", "Max_Image_Buffer_Memory", Form::Value},
    {"MV", "Version", Form::Value},
    {"BM", "Bounding_Method", Form::Value},
    {"BS", "Render_Block_Size", Form::Value},
    {"RP", "Render_Pattern", Form::Value},
    {"RS", "Render_Block_Step", Form::Value},
    {"UD", "Draw_Vistas", Form::Toggle},
    {"UL", "Light_Buffer", Form::Toggle},
    {"UV", "Vista_Buffer", Form::Toggle},
    {"UR", "Remove_Bounds", Form::Toggle},
    {"SU", "Split_Unions", Form::Toggle},
    {"SP", "Preview_Start_Size", Form::Value},
    {"EP", "Preview_End_Size", Form::Value},
    {"GA", "All_Console", Form::OnValue, "All_File"},
    {"GD", "Debug_Console", Form::OnValue, "Debug_File"},
    {"GF", "Fatal_Console", Form::OnValue, "Fatal_File"},
    {"GR", "Render_Console", Form::OnValue, "Render_File"},
    {"GS", "Statistic_Console", Form::OnValue, "Statistic_File"},
    {"GW", "Warning_Console", Form::OnValue, "Warning_File"},
    {"GP", "Append_File", Form::Toggle},
    {"GI", "Create_Ini", Form::Value},
    {"HI", "Include_Header", Form::Value},
    {"HR", "High_Reproducibility", Form::Toggle},
    {"TH", "Dither", Form::OnValue, "Dither_Method"},
    {"RF", "Radiosity_File_Name", Form::Value},
    {"RFI", "Radiosity_From_File", Form::Toggle},
    {"RFO", "Radiosity_To_File", Form::Toggle},
    {"RVP", "Radiosity_Vain_Pretrace", Form::Toggle},
};

}  // namespace

const KeyInfo* findKey(const std::string& name) {
    // A hash table by lower-case name, made once: a line of an INI file costs one look-up, not a
    // scan of the table lowering every name (fuzz finding 29: 65536 lines of unknown keys took
    // over 10 s under the sanitizers).
    static const std::unordered_map<std::string, const KeyInfo*> byName = [] {
        std::unordered_map<std::string, const KeyInfo*> m;
        for (const KeyInfo& k : kKeys) m.emplace(lower(k.name), &k);  // the first of equal names wins, as the scan did
        return m;
    }();
    const auto it = byName.find(lower(name));
    return it == byName.end() ? nullptr : it->second;
}

const SwitchInfo* findSwitch(const std::string& body) {
    const SwitchInfo* best = nullptr;
    size_t bestLength = 0;
    for (const SwitchInfo& s : kSwitches) {
        const std::string letters = s.letters;
        if (letters.size() <= bestLength || body.size() < letters.size()) continue;
        bool match = true;
        for (size_t i = 0; i < letters.size(); ++i)
            if (std::toupper(static_cast<unsigned char>(body[i])) != letters[i]) match = false;
        if (match) {
            best = &s;
            bestLength = letters.size();
        }
    }
    return best;
}

}  // namespace rays::cli::pov
