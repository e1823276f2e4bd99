#pragma once

// Counts the dots the student has drawn.
struct Score
{
	int dots = 0;
};
