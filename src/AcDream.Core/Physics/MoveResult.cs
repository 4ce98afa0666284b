namespace AcDream.Core.Physics;

/// <summary>The answer to a <see cref="MoveRequest"/>: where the mover ends, what it met, and whom it touched.</summary>
/// <param name="Answer">The resolved position, cell, footing and outcome, as the spec's <see cref="ResolveResult"/>.</param>
/// <param name="Report">The floor under the answer and the wall that stopped or slid it, when <see cref="MoveRequest.WithReport"/> asked for them; default otherwise.</param>
/// <param name="TouchedCount">How many registered movers the move touched (blocking or not), in the order met along its path; the first ones, up to the span's length, are written into the caller's span. 0 with no mover near.</param>
/// <param name="Commit">The number of the movers' commit (<see cref="MoverRegistry.CommitNumber"/>) whose state the call read: 0 before the first commit.</param>
public readonly record struct MoveResult(ResolveResult Answer, MoveReport Report, int TouchedCount, long Commit);
