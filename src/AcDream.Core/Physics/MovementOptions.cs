namespace AcDream.Core.Physics;

/// <summary>
/// Opt-in effects beyond the spec for
/// <see cref="PhysicsEngine.Resolve(System.Numerics.Vector3, uint, System.Numerics.Vector3, float, in MovementOptions)"/>.
/// Every effect is off by default, and <c>default(MovementOptions)</c> reproduces the four-argument
/// <c>Resolve</c> bit for bit; an effect that is off costs one untaken branch.
/// </summary>
/// <remarks>Values are checked when set: an invalid one throws <see cref="ArgumentOutOfRangeException"/>.</remarks>
public readonly record struct MovementOptions
{
    private readonly float? _stepDownHeight;
    private readonly float? _sweepStepLength;
    private readonly MoverBody? _body;
    private readonly Motion _motion;

    /// <summary>No effects: the spec's literal engine.</summary>
    public static MovementOptions Literal => default;

    /// <summary>
    /// What a player uses, every effect: step down 1.5 m (<see cref="StepDownHeight"/>), the walkable-slope limit
    /// (<see cref="WalkableSlope"/>), sweeps of 0.48 m, a player's sphere radius (<see cref="SweepStepLength"/>), entry
    /// through doors only (<see cref="DoorsOnly"/>), the player's body (<see cref="Body"/>, <see cref="MoverBody.Player"/>),
    /// and the body in three dimensions: vertical motion (<see cref="Vertical"/>), footing (<see cref="Footing"/>) and edge
    /// slide (<see cref="EdgeSlide"/>).
    /// </summary>
    public static MovementOptions Player => new()
    {
        StepDownHeight = 1.5f,
        WalkableSlope = true,
        SweepStepLength = 0.48f,
        DoorsOnly = true,
        Body = MoverBody.Player,
        Vertical = true,
        Footing = true,
        EdgeSlide = true,
    };

    /// <summary>
    /// Step down / airborne, metres ≥ 0. Ground (terrain or floor) more than this below the mover's
    /// feet is not snapped to: the mover keeps its Z, moves horizontally and is reported airborne
    /// (<c>IsOnGround</c> false) over the cell whose surface is below it, and the caller's gravity
    /// brings it down. Ground within this height below is snapped to (walking down stairs and hills).
    /// A falling caller passes 0 so that it lands exactly when its Z reaches the ground.
    /// </summary>
    /// <value>Null (the default): off, always snap to the ground, as the spec does.</value>
    public float? StepDownHeight
    {
        get => _stepDownHeight;
        init => _stepDownHeight = value is not float v || (float.IsFinite(v) && v >= 0f)
            ? value
            : throw new ArgumentOutOfRangeException(nameof(StepDownHeight), value, "StepDownHeight must be a finite height ≥ 0 m, or null for off.");
    }

    /// <summary>
    /// Walkable slope: a move that climbs onto terrain whose unit normal Z is below
    /// <see cref="PhysicsConstants.FloorZ"/> (steeper than about 48.4°) is rejected, as in the game.
    /// Moves down or across such a slope are allowed, so a mover on one is never frozen. Indoor
    /// floors are walkable by definition. Off (the default): only the step height limits climbing.
    /// </summary>
    public bool WalkableSlope { get; init; }

    /// <summary>
    /// Swept movement, metres &gt; 0: a delta longer than this is resolved as equal sub-steps no longer
    /// than it, stopping at the first sub-step that is rejected, so a fast mover cannot skip a wall,
    /// a cliff or a gap. The game uses the mover's sphere radius (0.48 m for a player). At most
    /// 65,536 sub-steps are taken; a longer delta gets longer sub-steps.
    /// </summary>
    /// <value>Null (the default): off, the spec's end-point check.</value>
    public float? SweepStepLength
    {
        get => _sweepStepLength;
        init => _sweepStepLength = value is not float v || (float.IsFinite(v) && v > 0f)
            ? value
            : throw new ArgumentOutOfRangeException(nameof(SweepStepLength), value, "SweepStepLength must be a finite length > 0 m, or null for off.");
    }

    /// <summary>
    /// Doors only: an outdoor mover enters a cell only by crossing one of that cell's portals to the
    /// outdoors; stepping onto the floor of any cell within step range elsewhere is rejected, as the
    /// building's outer wall would stop it in the game. Off (the default): the spec's entry wherever
    /// a floor lies under the mover.
    /// </summary>
    public bool DoorsOnly { get; init; }

    /// <summary>
    /// The mover's body: an upright cylinder of <see cref="MoverBody.Radius"/> and
    /// <see cref="MoverBody.Height"/> standing on the feet. Its horizontal move is swept against the
    /// walls of the cells around it (every physics polygon that is not a floor or a doorway's cover,
    /// where it reaches between the step height above the feet and the body's top) in closed form,
    /// and slides along them: it stops at contact and the rest of the move continues along the wall,
    /// up to <see cref="PhysicsConstants.MaxBodyContacts"/> walls per call; a concave corner stops it.
    /// Outdoors it meets the walls of buildings' cells, so it enters a building only through a doorway.
    /// With <see cref="WalkableSlope"/>, a slope too steep to climb slides it along the slope's contour.
    /// The cell the mover ends in is decided by its centre, as for a point. See <c>docs/physics.md</c>.
    /// </summary>
    /// <value>Null (the default): off, the mover is a point at its feet.</value>
    /// <exception cref="ArgumentOutOfRangeException">On set: a body with a zero radius or height (<c>default(MoverBody)</c>).</exception>
    public MoverBody? Body
    {
        get => _body;
        init => _body = value is not MoverBody b || b.IsValid
            ? value
            : throw new ArgumentOutOfRangeException(nameof(Body), value, "Body must have a radius and a height > 0 m (default(MoverBody) has neither), or be null for off.");
    }

    /// <summary>
    /// Vertical motion, swept (needs <see cref="Body"/>; ignored without one): the Z of the delta moves the body
    /// too. A body whose feet stand on the ground at the start and whose delta has no Z walks as without this
    /// effect (stepping up and down). Otherwise it is in the air: its horizontal move does not step down and
    /// climbs at most <see cref="PhysicsConstants.AirStepUp"/>; rising, its top stops under the first ceiling,
    /// lintel, upper floor or object's underside over its disc (<see cref="ResolveOutcome.Ceiling"/>, with that
    /// surface's normal); falling, it lands on the first floor under it (terrain, a cell's or an object's floor)
    /// at the point of contact, through floors of any thickness at any speed. Moves longer than
    /// <see cref="SweepStepLength"/> are taken in equal sub-steps, each horizontal then vertical. The engine keeps
    /// no state: the caller keeps its vertical speed, and zeroes it when the answer is on the ground (a landing)
    /// or reports <see cref="ResolveOutcome.Ceiling"/> (a head hit).
    /// </summary>
    /// <value>False (the default): off, the delta's Z is ignored, as the spec does.</value>
    public bool Vertical
    {
        get => (_motion & Motion.Vertical) != 0;
        init => _motion = value ? _motion | Motion.Vertical : _motion & ~Motion.Vertical;
    }

    /// <summary>
    /// Footing by the body (needs <see cref="Body"/>; ignored without one): the body stands on a floor (a cell's or
    /// an object's) that lies under any part of its footprint within the game's support reach, half its radius past
    /// the floor's edge (<see cref="PhysicsConstants.SupportReach"/>; 0.24 m for the player), not only on the ground
    /// under its centre: it stays on a plinth whose edge its centre has passed by less than that, and climbs
    /// the treads under its edge. Among floors within reach it stands on the highest that is no more than the step
    /// above its feet (and, when it would step down, no more than the step down below them).
    /// </summary>
    /// <value>False (the default): off, the body stands on the point under its centre.</value>
    public bool Footing
    {
        get => (_motion & Motion.Footing) != 0;
        init => _motion = value ? _motion | Motion.Footing : _motion & ~Motion.Footing;
    }

    /// <summary>
    /// Edge slide, the game's precipice slide for players (needs <see cref="Body"/>; ignored without one): a body that
    /// stands on a floor at the start and whose move would leave it in the air over a drop deeper than
    /// <see cref="StepDownHeight"/> slides along the floor's edge instead, keeping the part of its move along the
    /// edge (<see cref="ResolveOutcome.Slid"/>, the edge's outward normal, horizontal); head on, or where sliding
    /// finds no footing either, it stays where it is (<see cref="ResolveOutcome.Edge"/>). A delta with a Z
    /// (<see cref="Vertical"/>: a jump or a fall) is not held at edges.
    /// </summary>
    /// <value>False (the default): off, a body walks off an edge and is airborne.</value>
    public bool EdgeSlide
    {
        get => (_motion & Motion.EdgeSlide) != 0;
        init => _motion = value ? _motion | Motion.EdgeSlide : _motion & ~Motion.EdgeSlide;
    }

    /// <summary>Whether any effect of the body in three dimensions is on (vertical motion, footing, edge slide) with a body.</summary>
    internal bool InThreeD => _motion != 0 && _body.HasValue;

    /// <summary>Whether vertical motion is on with a body (without one it is ignored).</summary>
    internal bool MovesVertically => (_motion & Motion.Vertical) != 0 && _body.HasValue;

    /// <summary>The effects of the body in three dimensions, one bit each.</summary>
    [Flags]
    private enum Motion : byte
    {
        Vertical = 1,
        Footing = 2,
        EdgeSlide = 4,
    }
}
