// answers.cpp - the figures' answers from a native build of the same geometry, for the test.
//
// Reads one question a line, "FIGURE number number ...", the numbers a figure passed to its
// answer function (figures.cpp), and prints that function's answer as numbers on one line.
// slides/tests/interactive.mjs drags each figure in Chromium, where the answer comes from the
// WebAssembly build, and checks what the figure shows against these lines.
#include <cstdio>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

extern "C"
{
    void boxesAnswer(float, float, float, float, float, float, float, float, float*);
    void pointInBoxAnswer(float, float, float, float, float, float, float*);
    void circlesAnswer(float, float, float, float, float, float, float*);
    void orientedBoxesAnswer(float, float, float, float, float, float, float, float, float, float,
                             float*);
    void rayAnswer(float, float, float, float, float, float, float, float, float*);
    void sweptBoxAnswer(float, float, float, float, float, float, float, float, float, float,
                        float*);
}

int main()
{
    std::string line;
    while (std::getline(std::cin, line))
    {
        std::istringstream words(line);
        std::string figure;
        words >> figure;
        std::vector<float> in;
        for (float number = 0.f; words >> number;)
            in.push_back(number);
        in.resize(10, 0.f);
        float out[32] = {};
        if (figure == "boxes")
            boxesAnswer(in[0], in[1], in[2], in[3], in[4], in[5], in[6], in[7], out);
        else if (figure == "pointInBox")
            pointInBoxAnswer(in[0], in[1], in[2], in[3], in[4], in[5], out);
        else if (figure == "circles")
            circlesAnswer(in[0], in[1], in[2], in[3], in[4], in[5], out);
        else if (figure == "orientedBoxes")
            orientedBoxesAnswer(in[0], in[1], in[2], in[3], in[4], in[5], in[6], in[7], in[8],
                                in[9], out);
        else if (figure == "ray")
            rayAnswer(in[0], in[1], in[2], in[3], in[4], in[5], in[6], in[7], out);
        else if (figure == "sweptBox")
            sweptBoxAnswer(in[0], in[1], in[2], in[3], in[4], in[5], in[6], in[7], in[8], in[9],
                           out);
        else
        {
            std::cerr << "answers: no figure called '" << figure << "'\n";
            return 2;
        }
        for (float value : out)
            std::printf("%.9g ", double(value));
        std::printf("\n");
        std::fflush(stdout);
    }
    return 0;
}
