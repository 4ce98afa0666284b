using System.Numerics;
using AcDream.Core.Physics;

namespace AcDream.App.Movement;

/// <summary>
/// Where a <see cref="ChaseCamera"/> put its eye for one frame.
/// </summary>
/// <param name="Pivot">The point the boom starts from, <see cref="ChaseCamera.PivotHeight"/> above the feet (lower only under a ceiling nearer than that), world metres.</param>
/// <param name="PivotCellId">The cell the pivot is in, <c>0xXXYYCCCC</c>.</param>
/// <param name="Eye">The viewer sphere's centre, world metres.</param>
/// <param name="EyeCellId">The cell the eye is in, <c>0xXXYYCCCC</c>, as the engine's cast followed it through portals and seams.</param>
/// <param name="Length">How far the eye is from the pivot, metres: <see cref="ChaseCamera.BoomLength"/> when nothing was met, never below <see cref="ChaseCamera.MinBoom"/>.</param>
/// <param name="PulledIn">Whether the boom met something (a wall, a floor, a closed door, land not loaded) and the eye stopped short of its end.</param>
/// <param name="Met">What the boom met first (<see cref="SurfaceKind"/>); <see cref="SurfaceKind.None"/> when nothing, or land not loaded.</param>
/// <param name="MetId">Whose it is (the cast's <see cref="CastHit.Id"/>: a cell, an object or a mover); 0 when nothing.</param>
/// <param name="Contact">The sphere's centre where the boom met something; <paramref name="Eye"/> when nothing.</param>
/// <param name="Slid">Whether the boom met something nearer than <see cref="ChaseCamera.MinBoom"/> and the eye slid along it to that distance, off the boom's line.</param>
/// <param name="Overlapping">Whether the slide was blocked too (boxed in on all sides), so the eye sits <see cref="ChaseCamera.MinBoom"/> along the boom inside what it met.</param>
public readonly record struct CameraView(
    Vector3 Pivot,
    uint PivotCellId,
    Vector3 Eye,
    uint EyeCellId,
    float Length,
    bool PulledIn,
    SurfaceKind Met,
    uint MetId,
    Vector3 Contact,
    bool Slid,
    bool Overlapping)
{
    /// <summary>How much shorter than <see cref="ChaseCamera.BoomLength"/> the boom is, metres (0 when nothing was met).</summary>
    public float PulledInBy => MathF.Max(0f, ChaseCamera.BoomLength - Length);
}

/// <summary>
/// A chase camera with the game's defaults: a viewer sphere of <see cref="ViewerRadius"/> on a boom from a pivot
/// <see cref="PivotHeight"/> above the player's feet, <see cref="BoomBack"/> back (opposite the heading) and
/// <see cref="BoomUp"/> up. Each <see cref="Update"/> casts the sphere along the boom through the engine
/// (<see cref="PhysicsEngine.Cast"/>), passing creatures, players and open doors, and puts the eye short of what it meets.
/// </summary>
/// <remarks>
/// <para>
/// The pivot's cell is the cell the pivot is in, followed from frame to frame: a ray (radius 0) from the last frame's
/// pivot, in its cell, to this frame's, through the portals and seams between. The player's own cell is not always
/// the pivot's: the engine puts a player in the air over a floor opening in the cell below it, however high above the
/// opening it is (a jump into the cottage's cellar is in the cellar 0x0147 while its feet are still in the main room).
/// On the first frame, after <see cref="Reset"/>, after a move of more than <see cref="MaxFollow"/>, or when that ray
/// meets something, the ray goes up to the pivot from <see cref="FootLift"/> above the feet, in the player's cell; a
/// ceiling nearer than the pivot then lowers the pivot to <see cref="Skin"/> below it.
/// </para>
/// <para>
/// The boom: the sphere is cast from the pivot to the boom's end. When it meets something, the eye is pulled back
/// <see cref="Skin"/> along the boom from the contact. The eye is never nearer the pivot than <see cref="MinBoom"/>:
/// when the contact is nearer than that (the player backed against a wall), the eye slides from the contact along
/// what it met, off it by the skin, to <see cref="MinBoom"/> from the pivot, each slide a cast (at most
/// <see cref="MaxSlides"/>; a second surface met turns the slide along the line where the two meet). When every slide
/// is blocked the eye sits <see cref="MinBoom"/> along the boom although it overlaps what it met
/// (<see cref="CameraView.Overlapping"/>): the minimum length wins over clearance.
/// </para>
/// <para>
/// The eye's cell is the engine's: the cast's end when the boom met nothing, else a ray from the pivot (or the slide's
/// start) to the eye. One frame is two casts, three when the boom is pulled in; nothing is allocated.
/// </para>
/// </remarks>
public sealed class ChaseCamera
{
    /// <summary>The viewer sphere's radius: 0.3 m.</summary>
    public const float ViewerRadius = 0.3f;

    /// <summary>The pivot's height above the feet: 1.5 m.</summary>
    public const float PivotHeight = 1.5f;

    /// <summary>How far the boom reaches back from the pivot, opposite the heading: 2.5 m.</summary>
    public const float BoomBack = 2.5f;

    /// <summary>How far the boom rises from the pivot: 0.75 m.</summary>
    public const float BoomUp = 0.75f;

    /// <summary>The shortest boom: 0.5 m from the pivot.</summary>
    public const float MinBoom = 0.5f;

    /// <summary>How far the eye stops short of what the sphere met: 0.01 m.</summary>
    public const float Skin = 0.01f;

    /// <summary>
    /// How far above the feet the pivot's ray starts: 0.05 m, clear of the floor the feet stand on (a cast starting on
    /// it and moving up is free of it; one starting a rounding below it, as a feet position far out may be, would not be).
    /// </summary>
    public const float FootLift = 0.05f;

    /// <summary>The farthest the pivot is followed from the last frame's (see the remarks): 10 m; farther, it is found from the feet again.</summary>
    public const float MaxFollow = 10f;

    /// <summary>The most slides along what the boom met (see the remarks): 3.</summary>
    public const int MaxSlides = 3;

    /// <summary>The boom's full length, metres: √(2.5² + 0.75²) ≈ 2.61 m.</summary>
    public static readonly float BoomLength = MathF.Sqrt((BoomBack * BoomBack) + (BoomUp * BoomUp));

    private readonly PhysicsEngine _engine;
    private readonly CastOptions _sphere;
    private readonly CastOptions _ray;
    private readonly uint _playerId;

    // The last frame's pivot and its cell, which the next frame's pivot is followed from.
    private Vector3 _lastPivot;
    private uint _lastPivotCell;
    private bool _following;

    /// <summary>A camera over <paramref name="engine"/>.</summary>
    /// <param name="engine">The world it casts through.</param>
    /// <param name="playerId">The player's mover id, which its casts pass (0: none; they pass players anyway).</param>
    public ChaseCamera(PhysicsEngine engine, uint playerId = 0)
    {
        ArgumentNullException.ThrowIfNull(engine);
        _engine = engine;
        _sphere = new CastOptions(ViewerRadius, CastFilter.IgnoreCreatures | CastFilter.SolidOnly);
        _ray = _sphere with { Radius = 0f };
        _playerId = playerId;
    }

    /// <summary>The casts' options: the viewer sphere, passing creatures, players and open doors (and the player's own id, <see cref="PlayerId"/>).</summary>
    public CastOptions Options => _sphere;

    /// <summary>The player's mover id, which every cast of the camera passes (0: none).</summary>
    public uint PlayerId => _playerId;

    /// <summary>Places the eye for a player standing at <paramref name="feet"/> in <paramref name="cellId"/>, facing <paramref name="heading"/>.</summary>
    /// <param name="feet">The player's feet, world metres.</param>
    /// <param name="cellId">The player's cell, <c>0xXXYYCCCC</c>.</param>
    /// <param name="heading">Compass heading, radians (0 north, π/2 east), as <see cref="PlayerMovementMode.Heading"/>: the boom points the other way.</param>
    /// <exception cref="ArgumentException">The engine refuses the cast (a position not finite, a cell not of the world).</exception>
    public CameraView Update(Vector3 feet, uint cellId, float heading)
    {
        (Vector3 pivot, uint pivotCell) = Pivot(feet, cellId);
        (_lastPivot, _lastPivotCell, _following) = (pivot, pivotCell, true);

        (float sin, float cos) = MathF.SinCos(heading);
        var offset = new Vector3(-sin * BoomBack, -cos * BoomBack, BoomUp);
        Vector3 wanted = pivot + offset;
        CastHit boom = Cast(pivot, pivotCell, wanted, in _sphere);
        if (!boom.Hit)
        {
            return new CameraView(pivot, pivotCell, wanted, boom.CellId, BoomLength, false, SurfaceKind.None, 0, wanted, false, false);
        }

        Vector3 along = offset / BoomLength;
        float reach = (boom.Fraction * BoomLength) - Skin;
        if (reach >= MinBoom)
        {
            Vector3 eye = pivot + (along * reach);
            uint eyeCell = Cast(pivot, pivotCell, eye, in _ray).CellId; // (a ray: the eye's cell, the sphere having stopped short of it)
            return new CameraView(pivot, pivotCell, eye, eyeCell, reach, true, boom.Kind, boom.Id, boom.Position, false, false);
        }

        if (Slide(pivot, wanted, boom, out Vector3 slid, out uint slidCell))
        {
            return new CameraView(pivot, pivotCell, slid, slidCell, Vector3.Distance(pivot, slid), true, boom.Kind, boom.Id, boom.Position, true, false);
        }

        // Boxed in: the shortest boom, along its line, whatever it overlaps; its cell as a ray reaches it.
        Vector3 shortest = pivot + (along * MinBoom);
        uint shortestCell = Cast(pivot, pivotCell, shortest, in _ray).CellId;
        return new CameraView(pivot, pivotCell, shortest, shortestCell, MinBoom, true, boom.Kind, boom.Id, boom.Position, false, true);
    }

    /// <summary>
    /// Forgets the last frame's pivot: the next <see cref="Update"/> finds the pivot's cell from the feet. For a player
    /// moved other than by walking (a teleport, a portal).
    /// </summary>
    public void Reset() => _following = false;

    /// <summary>The pivot and its cell: followed from the last frame's pivot, else up from the feet.</summary>
    private (Vector3 Pivot, uint CellId) Pivot(Vector3 feet, uint cellId)
    {
        Vector3 top = feet + new Vector3(0f, 0f, PivotHeight);
        if (_following && Vector3.DistanceSquared(_lastPivot, top) <= MaxFollow * MaxFollow)
        {
            CastHit follow = Cast(_lastPivot, _lastPivotCell, top, in _ray);
            if (!follow.Hit)
            {
                return (top, follow.CellId);
            }
        }

        Vector3 foot = feet + new Vector3(0f, 0f, FootLift);
        CastHit up = Cast(foot, cellId, top, in _ray);
        if (!up.Hit)
        {
            return (top, up.CellId);
        }

        Vector3 pivot = foot + new Vector3(0f, 0f, MathF.Max(0f, (up.Fraction * (PivotHeight - FootLift)) - Skin));
        return (pivot, pivot == foot ? cellId : Cast(foot, cellId, pivot, in _ray).CellId);
    }

    /// <summary>
    /// From the boom's contact, slides the sphere along what it met (and along the line where it meets a second
    /// surface) to <see cref="MinBoom"/> from the pivot, <see cref="Skin"/> off the surfaces met; false when every
    /// slide is blocked or has nowhere to go.
    /// </summary>
    private bool Slide(Vector3 pivot, Vector3 wanted, CastHit contact, out Vector3 eye, out uint eyeCell)
    {
        Vector3 at = contact.Position, first = contact.Normal, second = Vector3.Zero;
        uint atCell = contact.CellId;
        for (int slide = 0; slide < MaxSlides; slide++)
        {
            // The way still wanted, kept out of the surfaces met: along the first one, or the line of two.
            Vector3 rest = wanted - at;
            Vector3 way;
            if (second == Vector3.Zero)
            {
                way = rest - (first * MathF.Min(0f, Vector3.Dot(rest, first)));
            }
            else
            {
                Vector3 line = Vector3.Cross(first, second);
                float lineLength = line.Length();
                way = lineLength < 1e-4f ? Vector3.Zero : line * (Vector3.Dot(rest, line) / (lineLength * lineLength));
            }

            float wayLength = way.Length();
            if (!(wayLength > 1e-5f))
            {
                break;
            }

            // Off the surfaces by the skin, then along the way to MinBoom from the pivot: |start + way·t − pivot| = MinBoom.
            Vector3 direction = way / wayLength;
            Vector3 start = at + ((first + second) * Skin);
            Vector3 fromPivot = start - pivot;
            float b = Vector3.Dot(direction, fromPivot);
            float c = fromPivot.LengthSquared() - (MinBoom * MinBoom);
            float t = c >= 0f ? 0f : -b + MathF.Sqrt((b * b) - c); // from inside that sphere, the one way out along the way
            Vector3 target = start + (direction * t);
            CastHit hit = Cast(at, atCell, target, in _sphere);
            if (!hit.Hit)
            {
                eye = target;
                eyeCell = hit.CellId;
                return true;
            }

            if (hit.Kind == SurfaceKind.None)
            {
                break; // land not loaded
            }

            at = hit.Position;
            atCell = hit.CellId;
            if (second == Vector3.Zero)
            {
                second = first;
                first = hit.Normal;
            }
            else
            {
                (first, second) = (hit.Normal, first);
            }
        }

        eye = default;
        eyeCell = 0;
        return false;
    }

    /// <summary>One cast of the camera from <paramref name="from"/> to <paramref name="to"/>, passing the player.</summary>
    private CastHit Cast(Vector3 from, uint fromCellId, Vector3 to, in CastOptions options) =>
        _engine.Cast(new CastRequest(from, fromCellId, to - from) { Options = options, MoverId = _playerId });
}
