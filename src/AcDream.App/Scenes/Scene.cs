using System.Numerics;
using AcDream.Core.Physics;

namespace AcDream.App.Scenes;

/// <summary>A scripted walk over the Holtburg world (format: <c>docs/scenes.md</c>).</summary>
/// <param name="Name">Shown in the summary and used for the SVG's file name.</param>
/// <param name="Source">Where the scene came from (a path, or "embedded default").</param>
/// <param name="Start">Start point, world metres (world (0, 0) = south-west corner of 0xA9B4); the mover starts on the ground there.</param>
/// <param name="StartHeadingDegrees">Compass heading at the start, degrees (0 north, 90 east).</param>
/// <param name="Legs">The legs, run in order.</param>
/// <param name="Notes">Lines printed under the summary.</param>
/// <param name="Effects">The engine's opt-in effects the walk uses (<c>"effects"</c>; default none).</param>
/// <param name="World">The world walked (<c>"world"</c>, <see cref="World.HoltburgWorld.Worlds"/>; default Holtburg).</param>
/// <param name="Objects">The object sets registered (<c>"objects"</c>, <see cref="World.HoltburgWorld.ObjectSets"/>; default none).</param>
/// <param name="Creatures">The creatures (<c>"creatures"</c>; default none), in order: creature i has the mover id <c>SceneRunner.FirstCreatureId + i</c>.</param>
/// <param name="Doors">The doors registered (<c>"doors"</c>, <see cref="World.HoltburgWorld.DoorSets"/>; default none), closed until a leg opens them.</param>
/// <param name="Pointers">The pointer rays cast after legs (<c>"pointers"</c>; default none), in order.</param>
internal sealed record Scene(string Name, string Source, Vector2 Start, float StartHeadingDegrees, IReadOnlyList<SceneLeg> Legs, IReadOnlyList<string> Notes, MovementOptions Effects,
    string World = World.HoltburgWorld.Worlds.Holtburg, IReadOnlyList<string>? Objects = null, IReadOnlyList<SceneCreature>? Creatures = null, IReadOnlyList<string>? Doors = null,
    IReadOnlyList<ScenePointer>? Pointers = null)
{
    /// <summary>The world this scene walks, with its objects.</summary>
    public World.HoltburgWorld CreateWorld() => new(World, Objects ?? []);
}
