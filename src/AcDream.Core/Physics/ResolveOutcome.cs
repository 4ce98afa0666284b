namespace AcDream.Core.Physics;

/// <summary>What happened to a move: see <see cref="ResolveResult.Outcome"/>.</summary>
public enum ResolveOutcome : byte
{
    /// <summary>The move was made (on the ground, or airborne with step down).</summary>
    Moved = 0,

    /// <summary>The body touched a wall and moved on along it (or stopped at it part way): moved; the wall's normal is reported.</summary>
    Slid,

    /// <summary>The land under the mover is not loaded: it is held where it is, on the ground.</summary>
    Held,

    /// <summary>Refused: the ground or floor ahead rises more than the step height.</summary>
    StepTooHigh,

    /// <summary>Refused (walkable slope): the terrain ahead is too steep to climb.</summary>
    SlopeTooSteep,

    /// <summary>Refused by a wall, indoors or outdoors: no floor and no portal ahead in a cell, a doorway's wall, a portal to a cell the engine does not have, or a cell's or object's wall that stops the point's step line or the body (which then did not move).</summary>
    Wall,

    /// <summary>Refused outdoors by a building's outer wall: a wall of its shell, or with doors only the building's footprint away from its doors; only its doors let a mover in.</summary>
    OuterWall,

    /// <summary>Refused: the land ahead is not loaded.</summary>
    UnloadedAhead,

    /// <summary>Refused: the move would leave the world.</summary>
    EdgeOfWorld,

    /// <summary>Refused (edge slide): the move would step off a drop deeper than the step down, and sliding along the edge found no footing either (head on).</summary>
    Edge,

    /// <summary>
    /// With vertical motion: the rising body's top met a ceiling, a lintel, an upper floor or an object's underside
    /// and stopped under it (the surface's unit normal, facing down, is reported): moved; the caller zeroes its
    /// upward speed.
    /// </summary>
    Ceiling,
}
