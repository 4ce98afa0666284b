using System.Numerics;
using AcDream.Core.Physics;

namespace AcDream.App.Movement;

/// <summary>What a <see cref="Pointer"/> ray met: the point under it, as click-to-walk or targeting reads it.</summary>
/// <param name="Hit">Whether the ray met something within <see cref="Pointer.MaxLength"/> (or land not loaded: <see cref="Kind"/> <see cref="SurfaceKind.None"/>).</param>
/// <param name="Point">The point met, world metres; the ray's end when it met nothing.</param>
/// <param name="Distance">How far along the ray, metres.</param>
/// <param name="Normal">The unit normal there, pointing back at the eye's side; zero when it met nothing.</param>
/// <param name="Kind">What it met: terrain, a cell's floor, wall or ceiling, an object, a building's shell, a mover.</param>
/// <param name="Id">Whose it is (<see cref="CastHit.Id"/>): the outdoor cell for terrain, the cell, the object's GfxObj/Setup id, or the mover's id; 0 when nothing.</param>
/// <param name="CellId">The cell the point is in: an indoor cell reached through portals, or the outdoor cell under it.</param>
public readonly record struct PointerHit(bool Hit, Vector3 Point, float Distance, Vector3 Normal, SurfaceKind Kind, uint Id, uint CellId);

/// <summary>
/// A pointer's ray through the world: from an eye along a direction, at most <see cref="MaxLength"/>, its first contact
/// (<see cref="PhysicsEngine.Cast"/> with radius 0). It stops at everything, doors open or closed and creatures
/// included (the engine's <see cref="CastFilter.None"/>), except the player's own mover.
/// </summary>
/// <param name="engine">The world it casts through.</param>
/// <param name="playerId">The player's mover id, which the ray passes (0: none).</param>
public sealed class Pointer(PhysicsEngine engine, uint playerId = 0)
{
    /// <summary>The longest ray: 100 m.</summary>
    public const float MaxLength = 100f;

    /// <summary>The shortest squared length of a direction measured as it is: below it the square has lost precision (or is 0).</summary>
    private const float MinSquaredLength = 1e-30f;

    private readonly PhysicsEngine _engine = engine ?? throw new ArgumentNullException(nameof(engine));
    private readonly CastOptions _options = new(0f, CastFilter.None);

    /// <summary>The ray's options: radius 0, no filter (the player's id, <see cref="PlayerId"/>, is passed).</summary>
    public CastOptions Options => _options;

    /// <summary>The player's mover id, which the ray passes (0: none).</summary>
    public uint PlayerId => playerId;

    /// <summary>The first thing under the ray from <paramref name="eye"/> along <paramref name="direction"/>.</summary>
    /// <param name="eye">Where the ray starts, world metres.</param>
    /// <param name="eyeCellId">The cell it starts in, <c>0xXXYYCCCC</c> (the camera's <see cref="CameraView.EyeCellId"/>; outdoors any outdoor number, 0 included).</param>
    /// <param name="direction">Its direction, any length above 0 (each component finite, one not zero; from float.Epsilon to float.MaxValue).</param>
    /// <exception cref="ArgumentException">The direction is zero or not finite, or the engine refuses the cast.</exception>
    public PointerHit Cast(Vector3 eye, uint eyeCellId, Vector3 direction)
    {
        float largest = MathF.Max(MathF.Abs(direction.X), MathF.Max(MathF.Abs(direction.Y), MathF.Abs(direction.Z)));
        if (!(float.IsFinite(direction.X) && float.IsFinite(direction.Y) && float.IsFinite(direction.Z) && largest > 0f))
        {
            throw new ArgumentException($"direction {direction} must be finite and not zero.", nameof(direction));
        }

        // A direction whose squared length over- or underflows a float (longer than about 1e19, or shorter than about
        // 1e-15) is measured once scaled so its largest component is 1; any other is measured as it is.
        float squared = direction.LengthSquared();
        Vector3 along = squared is >= MinSquaredLength and <= float.MaxValue ? direction : direction / largest;
        CastHit hit = _engine.Cast(new CastRequest(eye, eyeCellId, along * (MaxLength / along.Length())) { Options = _options, MoverId = playerId });
        return new PointerHit(hit.Hit, hit.Point, hit.Fraction * MaxLength, hit.Normal, hit.Kind, hit.Id, hit.CellId);
    }
}
