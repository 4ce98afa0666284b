using System.Numerics;

namespace AcDream.App.Movement;

/// <summary>What one <see cref="PlayerMovementMode.Update"/> did.</summary>
/// <param name="Steps">Physics steps taken (a frame, clamped to 1 s, is split into steps of at most 0.1 s): 0 for a zero-length frame, at most 10.</param>
/// <param name="RejectedSteps">Steps whose horizontal move the engine refused (the mover stayed where it was).</param>
/// <param name="RejectedFrom">World position (metres) before the last refused step; zero when none was refused.</param>
/// <param name="RejectedCellId">Cell id before the last refused step; 0 when none was refused.</param>
/// <param name="RejectedDelta">The horizontal move (world metres, Z = 0) of the last refused step; zero when none was refused.</param>
public readonly record struct MovementFrame(int Steps, int RejectedSteps, Vector3 RejectedFrom, uint RejectedCellId, Vector3 RejectedDelta);
